#include "curving/optimisation_patches.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace homesh {
namespace {

// 2D elements around each node, compressed rows: node i's are tris[start[i], start[i + 1]).
struct NodeTriangles {
  std::vector<int> start, tris;
};

NodeTriangles node_triangles(const Mesh& m) {
  NodeTriangles a;
  a.start.assign(m.num_nodes() + 1, 0);
  for (int e = 0; e < m.num_elements_2d(); ++e)
    for (int i : element_node_indices(m, e)) ++a.start[i + 1];
  std::partial_sum(a.start.begin(), a.start.end(), a.start.begin());
  a.tris.resize(a.start.back());
  std::vector<int> next(a.start.begin(), a.start.end() - 1);
  for (int e = 0; e < m.num_elements_2d(); ++e)
    for (int i : element_node_indices(m, e)) a.tris[next[i]++] = e;
  return a;
}

int find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::pair<double, double> element_lengths(const Mesh& m, const Eigen::Matrix2Xd& x, int e) {
  const auto nodes = element_node_indices(m, e);
  const Eigen::Vector2d a = x.col(nodes(0)), b = x.col(nodes(1)), c = x.col(nodes(2));
  if (e < m.num_triangles()) {
    const double edge = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const double area2 = std::abs((b - a)(0) * (c - a)(1) - (b - a)(1) * (c - a)(0));
    return {area2 / edge, edge};
  }
  const Eigen::Vector2d d = x.col(nodes(3));
  const double edge = std::max({(b - a).norm(), (c - b).norm(), (d - c).norm(), (a - d).norm()});
  // Twice the area of the straight quadrilateral: the cross product of its diagonals.
  const double area2 = std::abs((c - a)(0) * (d - b)(1) - (c - a)(1) * (d - b)(0));
  return {0.5 * area2 / edge, edge};
}

std::vector<OptimisationPatch> optimisation_patches(const Mesh& m, const std::vector<bool>& poor,
                                                    int layers, const std::vector<bool>& held) {
  const NodeTriangles around = node_triangles(m);
  const int nt = m.num_elements_2d();
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
      for (int i : element_node_indices(m, e)) {
        for (int j = around.start[i]; j < around.start[i + 1]; ++j)
          if (!in[around.tris[j]]) {
            in[around.tris[j]] = 1;
            grown.push_back(around.tris[j]);
          }
      }
    front.swap(grown);
  }
  // Free nodes: not held, every element round them in the set; they join their elements.
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
      for (int i : element_node_indices(m, e))
        if (is_free[i]) p.free_nodes.push_back(i);
    std::sort(p.free_nodes.begin(), p.free_nodes.end());
    p.free_nodes.erase(std::unique(p.free_nodes.begin(), p.free_nodes.end()), p.free_nodes.end());
  }
  patches.erase(std::remove_if(patches.begin(), patches.end(),
                               [](const OptimisationPatch& p) { return p.free_nodes.empty(); }),
                patches.end());
  return patches;
}

}  // namespace homesh
