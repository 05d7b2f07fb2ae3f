#include "quality/volume_validity.h"

#include <omp.h>

#include "core/error.h"

namespace homesh {

MeshValidity volume_validity(const VolumeMesh& m, const BoundsOptions& opt, int threads) {
  return volume_validity(m, MeshValidity{}, std::vector<int>{}, opt, threads);
}

MeshValidity volume_validity(const VolumeMesh& m, const MeshValidity& known,
                             const std::vector<int>& known_index, const BoundsOptions& opt,
                             int threads) {
  if (m.order > kMaxTetrahedronOrder)
    throw Error("certified validity of tetrahedra: order " + std::to_string(m.order) +
                " is above " + std::to_string(kMaxTetrahedronOrder) +
                ", the highest whose det J homesh bounds");
  const int n = m.num_tetrahedra();
  // known's bounds count only if refined by the same options.
  const bool reuse = !known_index.empty() && known.relative_tolerance == opt.relative_tolerance &&
                     known.max_subdivisions == opt.max_subdivisions;
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
    for (int e = 0; e < n; ++e) {
      const int k = reuse ? known_index[static_cast<std::size_t>(e)] : -1;
      if (k >= 0) {
        v.ratio(e) = known.ratio(k);
        v.min_det(e) = known.min_det(k);
        v.converged[e] = known.converged[static_cast<std::size_t>(k)];
        continue;
      }
      for (Eigen::Index i = 0; i < X.cols(); ++i) X.col(i) = m.x.col(m.tet(i, e));
      const JacobianBounds b = tetrahedron_jacobian_bounds(X, m.order, opt);
      v.ratio(e) = scaled_jacobian_ratio(b);
      v.min_det(e) = b.min_lower;
      v.converged[e] = b.converged;
    }
  }
  count_validity(v);
  return v;
}

MeshValidity volume_validity(const VolumeMesh& m, const VolumeMesh& previous,
                             const MeshValidity& known, const BoundsOptions& opt, int threads) {
  const int n = m.num_tetrahedra();
  if (previous.order != m.order || previous.num_tetrahedra() != n ||
      previous.tet.rows() != m.tet.rows() || known.ratio.size() != n)
    return volume_validity(m, opt, threads);
  // Tetrahedron e keeps its bounds where its nodes are where previous's were.
  std::vector<int> index(static_cast<std::size_t>(n), -1);
  for (int e = 0; e < n; ++e) {
    bool same = true;
    for (Eigen::Index i = 0; i < m.tet.rows() && same; ++i) {
      const int b = previous.tet(i, e);
      same = b < previous.num_nodes() && m.x.col(m.tet(i, e)) == previous.x.col(b);
    }
    if (same) index[static_cast<std::size_t>(e)] = e;
  }
  return volume_validity(m, known, index, opt, threads);
}

}  // namespace homesh
