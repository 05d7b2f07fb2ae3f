#include "quality/mesh_quality.h"

#include <Eigen/LU>
#include <algorithm>

#include "element/lagrange_basis.h"
#include "element/reference_nodes.h"
#include "quality/ideal_jacobian.h"

namespace homesh {

std::vector<MeshMeasure> mesh_measures(const Mesh& m, const std::vector<const Measure*>& qs,
                                       int lattice, Reference ref) {
  const int p = m.order, nodes = triangle_node_count(p), n = m.num_triangles();
  // Sample points: the lattice, plus the element nodes unless the lattice
  // already holds them (lattice a multiple of p); node_point[i] is node i's.
  Eigen::Matrix2Xd uv = reference_nodes(lattice);
  std::vector<int> node_point(static_cast<std::size_t>(nodes));
  if (lattice % p == 0) {
    const Eigen::Matrix2Xi on_lattice = reference_node_indices(lattice);
    const Eigen::Matrix2Xi node_index = reference_node_indices(p) * (lattice / p);
    for (int i = 0; i < nodes; ++i)
      for (int k = 0; k < on_lattice.cols(); ++k)
        if (on_lattice.col(k) == node_index.col(i)) node_point[i] = k;
  } else {
    const Eigen::Index l = uv.cols();
    uv.conservativeResize(2, l + nodes);
    uv.rightCols(nodes) = reference_nodes(p);
    for (int i = 0; i < nodes; ++i) node_point[i] = static_cast<int>(l) + i;
  }
  const ElementSampling sampling(p, uv);
  const int points = sampling.size();
  // The same gradients as `sampling`, as matrices: J at every point of an
  // element is then two small matrix products.
  Eigen::MatrixXd dNdu, dNdv;
  LagrangeBasis(p).tabulate_gradients(uv, dNdu, dNdv);
  const Eigen::Matrix2d to_ideal = reference_to_ideal_jacobian().inverse();

  std::vector<MeshMeasure> out(qs.size());
  for (auto& r : out) {
    r.element_min.resize(n);
    r.node_values.resize(nodes, n);
  }
#pragma omp parallel
  {
    Eigen::Matrix2Xd X(2, nodes), Ju(2, points), Jv(2, points);
    std::vector<Eigen::Matrix2d> W(static_cast<std::size_t>(points));
    std::vector<double> det(static_cast<std::size_t>(points)), value(det.size());
#pragma omp for schedule(static)
    for (int e = 0; e < n; ++e) {
      for (int i = 0; i < nodes; ++i) X.col(i) = m.x.col(m.tri(i, e));
      Ju.noalias() = X * dNdu;
      Jv.noalias() = X * dNdv;
      for (int k = 0; k < points; ++k) {
        Eigen::Matrix2d J;
        J << Ju(0, k), Jv(0, k), Ju(1, k), Jv(1, k);
        W[k].noalias() = J * to_ideal;  // W = J inv(J_ri), as ideal_jacobian
        det[k] = W[k].determinant();
      }
      for (std::size_t j = 0; j < qs.size(); ++j) {
        const Measure& q = *qs[j];
        ElementScale scale;
        if (!q.pointwise()) {
          scale.element_value = q.element(sampling, X);
        } else if (ref == Reference::element_max && q.thesis_max_normalised) {
          for (int k = 0; k < points; ++k)
            if (det[k] > 0.0) scale.max_raw = std::max(scale.max_raw, q.raw(W[k]));
        }
        double lowest = 1.0;
        for (int k = 0; k < points; ++k) {
          value[k] = point_quality(q, W[k], scale, ref);
          lowest = std::min(lowest, value[k]);
        }
        for (int i = 0; i < nodes; ++i) out[j].node_values(i, e) = value[node_point[i]];
        out[j].element_min(e) = lowest;
      }
    }
  }
  return out;
}

}  // namespace homesh
