#include "element/tet_lagrange_basis.h"

#include <string>

#include "core/error.h"
#include "core/mesh.h"
#include "element/silvester_factors.h"
#include "element/tet_reference_nodes.h"

namespace homesh {

TetLagrangeBasis::TetLagrangeBasis(int p) : p_(p) {
  if (p < 1 || p > kMaxOrder)
    throw Error("TetLagrangeBasis: order " + std::to_string(p) + " out of range 1.." +
                std::to_string(kMaxOrder));
  const Eigen::Matrix3Xi ijl = tetrahedron_node_indices(p);
  nodes_ = tetrahedron_nodes(p);
  multi_index_.resize(4, ijl.cols());
  multi_index_.row(0) = Eigen::RowVectorXi::Constant(ijl.cols(), p) - ijl.colwise().sum();
  multi_index_.bottomRows<3>() = ijl;
}

void TetLagrangeBasis::evaluate(const Eigen::Vector3d& uvw, double* N, double* dN) const {
  // R[d][m] = R_m(l_d) and dR[d][m] = R_m'(l_d) for the barycentric l_d.
  double R[4][kMaxOrder + 1];
  double dR[4][kMaxOrder + 1];
  const double l[4] = {1.0 - uvw(0) - uvw(1) - uvw(2), uvw(0), uvw(1), uvw(2)};
  for (int d = 0; d < 4; ++d) silvester_factors(p_, l[d], R[d], dR[d]);
  for (int k = 0; k < size(); ++k) {
    double r[4], dr[4];
    for (int d = 0; d < 4; ++d) {
      r[d] = R[d][multi_index_(d, k)];
      dr[d] = dR[d][multi_index_(d, k)];
    }
    if (N) N[k] = r[0] * r[1] * r[2] * r[3];
    if (dN) {
      // d l0 / du_r = -1, d l_{r+1} / du_r = 1.
      const double d0 = -dr[0] * r[1] * r[2] * r[3];
      dN[3 * k] = d0 + r[0] * dr[1] * r[2] * r[3];
      dN[3 * k + 1] = d0 + r[0] * r[1] * dr[2] * r[3];
      dN[3 * k + 2] = d0 + r[0] * r[1] * r[2] * dr[3];
    }
  }
}

Eigen::VectorXd TetLagrangeBasis::values(const Eigen::Vector3d& uvw) const {
  Eigen::VectorXd N(size());
  evaluate(uvw, N.data(), nullptr);
  return N;
}

Eigen::Matrix3Xd TetLagrangeBasis::gradients(const Eigen::Vector3d& uvw) const {
  Eigen::Matrix3Xd dN(3, size());
  evaluate(uvw, nullptr, dN.data());
  return dN;
}

}  // namespace homesh
