#include "core/group_by_entity.h"

#include <algorithm>
#include <numeric>

namespace homesh {
namespace {

// New position -> old of a stable sort by `entity`; empty if already sorted.
std::vector<int> order(const std::vector<int>& entity) {
  if (std::is_sorted(entity.begin(), entity.end())) return {};
  std::vector<int> perm(entity.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::stable_sort(perm.begin(), perm.end(), [&](int a, int b) { return entity[a] < entity[b]; });
  return perm;
}

template <typename T>
std::vector<T> permuted(const std::vector<T>& v, const std::vector<int>& perm) {
  std::vector<T> out(perm.size());
  for (std::size_t k = 0; k < perm.size(); ++k) out[k] = v[static_cast<std::size_t>(perm[k])];
  return out;
}

Eigen::MatrixXi permuted(const Eigen::MatrixXi& columns, const std::vector<int>& perm) {
  Eigen::MatrixXi out(columns.rows(), columns.cols());
  for (std::size_t k = 0; k < perm.size(); ++k)
    out.col(static_cast<Eigen::Index>(k)) = columns.col(perm[k]);
  return out;
}

}  // namespace

std::vector<int> group_by_entity(Mesh& m) {
  if (const auto p = order(m.point_entity); !p.empty()) {
    m.point_node = permuted(m.point_node, p);
    m.point_entity = permuted(m.point_entity, p);
  }
  if (const auto p = order(m.line_entity); !p.empty()) {
    m.line = permuted(m.line, p);
    m.line_entity = permuted(m.line_entity, p);
  }
  const auto t = order(m.tri_entity);
  if (!t.empty()) {
    m.tri = permuted(m.tri, t);
    m.tri_entity = permuted(m.tri_entity, t);
  }
  const auto q = order(m.quad_entity);
  if (!q.empty()) {
    m.quad = permuted(m.quad, q);
    m.quad_entity = permuted(m.quad_entity, q);
  }
  if (t.empty() && q.empty()) return {};
  // One permutation of the 2D elements, triangles then quadrilaterals.
  const int triangles = m.num_triangles();
  std::vector<int> p(static_cast<std::size_t>(m.num_elements_2d()));
  for (int e = 0; e < triangles; ++e) p[e] = t.empty() ? e : t[e];
  for (int e = 0; e < m.num_quads(); ++e) p[triangles + e] = triangles + (q.empty() ? e : q[e]);
  return p;
}

}  // namespace homesh
