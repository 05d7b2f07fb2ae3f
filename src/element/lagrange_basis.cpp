#include "element/lagrange_basis.h"

#include <string>

#include "core/error.h"
#include "element/reference_nodes.h"
#include "element/silvester_factors.h"

namespace homesh {

LagrangeBasis::LagrangeBasis(int p) : NodalBasis(p) {
  if (p < 1 || p > kMaxOrder)
    throw Error("LagrangeBasis: order " + std::to_string(p) + " out of range 1.." +
                std::to_string(kMaxOrder));
  const Eigen::Matrix2Xi ij = reference_node_indices(p);
  nodes_ = reference_nodes(p);
  multi_index_.resize(3, ij.cols());
  multi_index_.row(0) = Eigen::RowVectorXi::Constant(ij.cols(), p) - ij.row(0) - ij.row(1);
  multi_index_.bottomRows<2>() = ij;
}

void LagrangeBasis::evaluate(const Eigen::Vector2d& uv, double* N, double* dNdu,
                             double* dNdv) const {
  // R[d][m] = R_m(l_d) and dR[d][m] = R_m'(l_d) for the barycentric l_d.
  double R[3][kMaxOrder + 1];
  double dR[3][kMaxOrder + 1];
  const double l[3] = {1.0 - uv(0) - uv(1), uv(0), uv(1)};
  for (int d = 0; d < 3; ++d) silvester_factors(p_, l[d], R[d], dR[d]);
  const bool derivatives = dNdu != nullptr || dNdv != nullptr;
  for (int k = 0; k < size(); ++k) {
    const int c = multi_index_(0, k), a = multi_index_(1, k), b = multi_index_(2, k);
    const double r0 = R[0][c], r1 = R[1][a], r2 = R[2][b];
    if (N) N[k] = r0 * r1 * r2;
    if (derivatives) {
      // d l0 / du = d l0 / dv = -1, d l1 / du = 1, d l2 / dv = 1.
      const double d0 = -dR[0][c] * r1 * r2;
      if (dNdu) dNdu[k] = d0 + r0 * dR[1][a] * r2;
      if (dNdv) dNdv[k] = d0 + r0 * r1 * dR[2][b];
    }
  }
}

}  // namespace homesh
