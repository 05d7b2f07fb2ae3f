#include "quality/volume_validity.h"

#include <omp.h>

#include "core/error.h"

namespace homesh {
namespace {

// Bounds tetrahedron e of m into v (X: scratch for its nodes).
void bound_tetrahedron(const VolumeMesh& m, int e, const BoundsOptions& opt, Eigen::Matrix3Xd& X,
                       MeshValidity& v) {
  for (Eigen::Index i = 0; i < X.cols(); ++i) X.col(i) = m.x.col(m.tet(i, e));
  const JacobianBounds b = tetrahedron_jacobian_bounds(X, m.order, opt);
  v.ratio(e) = scaled_jacobian_ratio(b);
  v.min_det(e) = b.min_lower;
  v.converged[e] = b.converged;
}

}  // namespace

MeshValidity volume_validity(const VolumeMesh& m, const BoundsOptions& opt, int threads) {
  if (m.order > kMaxTetrahedronOrder)
    throw Error("certified validity of tetrahedra: order " + std::to_string(m.order) +
                " is above " + std::to_string(kMaxTetrahedronOrder) +
                ", the highest whose det J homesh bounds");
  const int n = m.num_tetrahedra();
  MeshValidity v;
  v.ratio.resize(n);
  v.min_det.resize(n);
  v.converged.assign(static_cast<std::size_t>(n), 0);
  v.relative_tolerance = opt.relative_tolerance;
  v.max_subdivisions = opt.max_subdivisions;
#pragma omp parallel num_threads(threads > 0 ? threads : omp_get_max_threads())
  {
    Eigen::Matrix3Xd X(3, m.tet.rows());
#pragma omp for schedule(dynamic, 64)
    for (int e = 0; e < n; ++e) bound_tetrahedron(m, e, opt, X, v);
  }
  count_validity(v);
  return v;
}

MeshValidity volume_validity(const VolumeMesh& m, const VolumeMesh& previous,
                             const MeshValidity& known) {
  const int n = m.num_tetrahedra();
  if (previous.order != m.order || previous.num_tetrahedra() != n ||
      previous.tet.rows() != m.tet.rows() || known.ratio.size() != n ||
      known.relative_tolerance != BoundsOptions{}.relative_tolerance ||
      known.max_subdivisions != BoundsOptions{}.max_subdivisions)
    return volume_validity(m);
  MeshValidity v = known;
  const BoundsOptions opt;
#pragma omp parallel
  {
    Eigen::Matrix3Xd X(3, m.tet.rows());
#pragma omp for schedule(dynamic, 256)
    for (int e = 0; e < n; ++e) {
      bool same = true;
      for (Eigen::Index i = 0; i < m.tet.rows() && same; ++i) {
        const int a = m.tet(i, e), b = previous.tet(i, e);
        same = b < previous.num_nodes() && m.x.col(a) == previous.x.col(b);
      }
      if (!same) bound_tetrahedron(m, e, opt, X, v);
    }
  }
  count_validity(v);
  return v;
}

}  // namespace homesh
