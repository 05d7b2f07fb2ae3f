#include "element/quad_lagrange_basis.h"

#include <string>

#include "core/error.h"
#include "element/line_lagrange.h"
#include "element/quad_reference_nodes.h"

namespace homesh {

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
