#include "curving/optimisation_patches.h"

#include <algorithm>
#include <numeric>

namespace homesh {
namespace {

// Triangles around each node, compressed rows: node i's are tris[start[i], start[i + 1]).
struct NodeTriangles {
  std::vector<int> start, tris;
};

NodeTriangles node_triangles(const Mesh& m) {
  NodeTriangles a;
  a.start.assign(m.num_nodes() + 1, 0);
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int k = 0; k < m.tri.rows(); ++k) ++a.start[m.tri(k, e) + 1];
  std::partial_sum(a.start.begin(), a.start.end(), a.start.begin());
  a.tris.resize(a.start.back());
  std::vector<int> next(a.start.begin(), a.start.end() - 1);
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int k = 0; k < m.tri.rows(); ++k) a.tris[next[m.tri(k, e)]++] = e;
  return a;
}

int find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<OptimisationPatch> optimisation_patches(const Mesh& m, const std::vector<bool>& poor,
                                                    int layers, const std::vector<bool>& held) {
  const NodeTriangles around = node_triangles(m);
  const int nt = m.num_triangles(), n = static_cast<int>(m.tri.rows());
  std::vector<char> in(nt, 0);
  std::vector<int> front;
  for (int e = 0; e < nt; ++e)
    if (poor[e]) {
      in[e] = 1;
      front.push_back(e);
    }
  for (int layer = 0; layer < layers && !front.empty(); ++layer) {
    std::vector<int> grown;
    for (int e : front)
      for (int k = 0; k < n; ++k) {
        const int i = m.tri(k, e);
        for (int j = around.start[i]; j < around.start[i + 1]; ++j)
          if (!in[around.tris[j]]) {
            in[around.tris[j]] = 1;
            grown.push_back(around.tris[j]);
          }
      }
    front.swap(grown);
  }
  // Free nodes: not held, every triangle round them in the set; they join their triangles.
  std::vector<int> parent(nt);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> is_free(m.num_nodes(), 0);
  for (int i = 0; i < m.num_nodes(); ++i) {
    if (held[i] || around.start[i] == around.start[i + 1]) continue;
    bool inside = true;
    for (int j = around.start[i]; j < around.start[i + 1] && inside; ++j)
      inside = in[around.tris[j]];
    if (!inside) continue;
    is_free[i] = 1;
    const int root = find(parent, around.tris[around.start[i]]);
    for (int j = around.start[i] + 1; j < around.start[i + 1]; ++j)
      parent[find(parent, around.tris[j])] = root;
  }
  std::vector<int> patch_of(nt, -1);
  std::vector<OptimisationPatch> patches;
  for (int e = 0; e < nt; ++e) {
    if (!in[e]) continue;
    const int root = find(parent, e);
    if (patch_of[root] < 0) {
      patch_of[root] = static_cast<int>(patches.size());
      patches.emplace_back();
    }
    patches[patch_of[root]].elements.push_back(e);
  }
  for (OptimisationPatch& p : patches) {
    for (int e : p.elements)
      for (int k = 0; k < n; ++k)
        if (is_free[m.tri(k, e)]) p.free_nodes.push_back(m.tri(k, e));
    std::sort(p.free_nodes.begin(), p.free_nodes.end());
    p.free_nodes.erase(std::unique(p.free_nodes.begin(), p.free_nodes.end()), p.free_nodes.end());
  }
  patches.erase(std::remove_if(patches.begin(), patches.end(),
                               [](const OptimisationPatch& p) { return p.free_nodes.empty(); }),
                patches.end());
  return patches;
}

}  // namespace homesh
