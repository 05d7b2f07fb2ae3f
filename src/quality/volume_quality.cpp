#include "quality/volume_quality.h"

#include <omp.h>

#include <Eigen/LU>
#include <algorithm>

#include "core/error.h"
#include "element/tet_lagrange_basis.h"
#include "element/tet_reference_nodes.h"
#include "quality/volume_measures.h"

namespace homesh {
namespace {

// The quality of measure m at the samples with maps W (one per sample) of one
// element: Q1 from the dets, the others pointwise, max-normalised if asked.
void sample_quality(const Measure& m, const std::vector<Eigen::Matrix3d>& W, Reference ref,
                    Eigen::Ref<Eigen::VectorXd> q) {
  const auto n = static_cast<Eigen::Index>(W.size());
  if (!m.quality3) {  // Q1
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& w : W) {
      lo = std::min(lo, w.determinant());
      hi = std::max(hi, w.determinant());
    }
    q.setConstant(lo > 0 && hi > 0 ? lo / hi : 0.0);
    return;
  }
  if (ref == Reference::element_max && m.thesis_max_normalised) {
    double top = 0;
    for (const auto& w : W)
      if (w.determinant() > 0) top = std::max(top, m.raw3(w));
    for (Eigen::Index k = 0; k < n; ++k)
      q(k) = W[k].determinant() > 0 && top > 0 ? m.raw3(W[k]) / top : 0.0;
    return;
  }
  for (Eigen::Index k = 0; k < n; ++k) q(k) = m.quality3(W[k]);
}

}  // namespace

std::vector<MeshMeasure> volume_quality(const VolumeMesh& m, const std::vector<const Measure*>& qs,
                                        int lattice, Reference ref, int threads) {
  if (lattice < 1) throw Error("volume quality: lattice order " + std::to_string(lattice) + " < 1");
  const int p = m.order, n = m.num_tetrahedra();
  const TetLagrangeBasis basis(p);
  // Samples: the lattice's points, then the element's nodes.
  const Eigen::Matrix3Xd lattice_points = tetrahedron_nodes(lattice), nodes = basis.nodes();
  std::vector<Eigen::Matrix3Xd> dN;
  for (Eigen::Index k = 0; k < lattice_points.cols(); ++k)
    dN.push_back(basis.gradients(lattice_points.col(k)));
  for (Eigen::Index k = 0; k < nodes.cols(); ++k) dN.push_back(basis.gradients(nodes.col(k)));
  const Eigen::Matrix3d& A = regular_tetrahedron_inverse();

  std::vector<MeshMeasure> out(qs.size());
  for (MeshMeasure& r : out) {
    r.element_min.resize(n);
    r.node_values.resize(nodes.cols(), n);
  }
#pragma omp parallel num_threads(threads > 0 ? threads : omp_get_max_threads())
  {
    std::vector<Eigen::Matrix3d> W(dN.size());
    Eigen::VectorXd q(static_cast<Eigen::Index>(dN.size()));
#pragma omp for schedule(dynamic, 64)
    for (int e = 0; e < n; ++e) {
      const Eigen::Matrix3Xd X = m.tetrahedron_nodes(e);
      for (std::size_t k = 0; k < dN.size(); ++k) W[k] = X * dN[k].transpose() * A;
      for (std::size_t j = 0; j < qs.size(); ++j) {
        sample_quality(*qs[j], W, ref, q);
        out[j].element_min(e) = q.minCoeff();
        out[j].node_values.col(e) = q.tail(nodes.cols());
      }
    }
  }
  return out;
}

}  // namespace homesh
