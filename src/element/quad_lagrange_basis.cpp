#include "element/quad_lagrange_basis.h"

#include <string>

#include "core/error.h"
#include "element/quad_reference_nodes.h"

namespace homesh {
namespace {

// L[i] = L_i(t) and dL[i] = L_i'(t), i = 0..p, the 1D Lagrange polynomials at
// the equispaced points s / p.
void line_lagrange(int p, double t, double* L, double* dL) {
  const double pt = p * t;
  for (int i = 0; i <= p; ++i) {
    double value = 1.0, derivative = 0.0;
    for (int s = 0; s <= p; ++s) {
      if (s == i) continue;
      const double f = (pt - s) / (i - s), df = static_cast<double>(p) / (i - s);
      derivative = derivative * f + value * df;
      value *= f;
    }
    L[i] = value;
    dL[i] = derivative;
  }
}

}  // namespace

QuadLagrangeBasis::QuadLagrangeBasis(int p) : NodalBasis(p) {
  if (p < 1 || p > kMaxOrder)
    throw Error("QuadLagrangeBasis: order " + std::to_string(p) + " out of range 1.." +
                std::to_string(kMaxOrder));
  index_ = quad_reference_node_indices(p);
  nodes_ = quad_reference_nodes(p);
}

void QuadLagrangeBasis::evaluate(const Eigen::Vector2d& uv, double* N, double* dNdu,
                                 double* dNdv) const {
  double Lu[kMaxOrder + 1], dLu[kMaxOrder + 1], Lv[kMaxOrder + 1], dLv[kMaxOrder + 1];
  line_lagrange(p_, uv(0), Lu, dLu);
  line_lagrange(p_, uv(1), Lv, dLv);
  for (int k = 0; k < size(); ++k) {
    const int i = index_(0, k), j = index_(1, k);
    if (N) N[k] = Lu[i] * Lv[j];
    if (dNdu) dNdu[k] = dLu[i] * Lv[j];
    if (dNdv) dNdv[k] = Lu[i] * dLv[j];
  }
}

}  // namespace homesh
