#pragma once
// The triangles round each node of a mesh, in one counting-sort pass: two flat
// arrays (compressed rows), not a vector per node, which costs an allocation
// per node (a third of the layers stage at 1e6 triangles). Triangles are listed
// in ascending order round each node.
#include <vector>

#include "core/mesh.h"

namespace homesh {

struct NodeTriangles {
  std::vector<int>
      first;  ///< #nodes + 1: node v's triangles are incident[first[v] .. first[v + 1])
  std::vector<int> incident;  ///< 3 #triangles triangle indices

  explicit NodeTriangles(const Mesh& m) : first(m.num_nodes() + 1, 0) {
    const int triangles = m.num_triangles();
    incident.resize(3 * static_cast<std::size_t>(triangles));
    for (int e = 0; e < triangles; ++e)
      for (int i = 0; i < 3; ++i) ++first[m.tri(i, e) + 1];
    for (int v = 0; v < m.num_nodes(); ++v) first[v + 1] += first[v];
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (int e = 0; e < triangles; ++e)
      for (int i = 0; i < 3; ++i) incident[fill[m.tri(i, e)]++] = e;
  }
  const int* begin(int v) const { return incident.data() + first[v]; }
  const int* end(int v) const { return incident.data() + first[v + 1]; }
};

}  // namespace homesh
