#include "core/volume_mesh.h"

#include <algorithm>
#include <numeric>

namespace homesh {
namespace {

// Sorts the columns of conn and the entries of entity by entity tag, stably;
// returns the permutation (empty if none was needed).
std::vector<int> sort_by_entity(Eigen::MatrixXi& conn, std::vector<int>& entity) {
  if (std::is_sorted(entity.begin(), entity.end())) return {};
  std::vector<int> perm(entity.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::stable_sort(perm.begin(), perm.end(), [&](int a, int b) { return entity[a] < entity[b]; });
  Eigen::MatrixXi sorted(conn.rows(), conn.cols());
  std::vector<int> tags(entity.size());
  for (std::size_t k = 0; k < perm.size(); ++k) {
    sorted.col(static_cast<Eigen::Index>(k)) = conn.col(perm[k]);
    tags[k] = entity[perm[k]];
  }
  conn = std::move(sorted);
  entity = std::move(tags);
  return perm;
}

}  // namespace

Eigen::Matrix3Xd VolumeMesh::tetrahedron_nodes(int e) const {
  Eigen::Matrix3Xd X(3, tet.rows());
  for (Eigen::Index i = 0; i < tet.rows(); ++i) X.col(i) = x.col(tet(i, e));
  return X;
}

Eigen::Vector3d VolumeMesh::corner_centroid(int e) const {
  return (x.col(tet(0, e)) + x.col(tet(1, e)) + x.col(tet(2, e)) + x.col(tet(3, e))) / 4.0;
}

std::vector<int> group_by_entity(VolumeMesh& m) {
  sort_by_entity(m.tri, m.tri_entity);
  sort_by_entity(m.line, m.line_entity);
  return sort_by_entity(m.tet, m.tet_entity);
}

}  // namespace homesh
