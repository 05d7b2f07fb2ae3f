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
  const auto p = order(m.tri_entity);
  if (!p.empty()) {
    m.tri = permuted(m.tri, p);
    m.tri_entity = permuted(m.tri_entity, p);
  }
  return p;
}

}  // namespace homesh
