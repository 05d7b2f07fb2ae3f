#include "quality/element_sampling.h"

#include <string>

#include "core/error.h"
#include "element/lagrange_basis.h"
#include "element/quad_lagrange_basis.h"

namespace homesh {

ElementSampling::ElementSampling(int p, const Eigen::Matrix2Xd& uv, ElementShape shape)
    : p_(p), shape_(shape), points_(uv) {
  if (shape == ElementShape::quadrilateral)
    QuadLagrangeBasis(p).tabulate_gradients(uv, dNdu_, dNdv_);
  else
    LagrangeBasis(p).tabulate_gradients(uv, dNdu_, dNdv_);
}

ElementSampling::ElementSampling(int p, const QuadratureRule& rule)
    : ElementSampling(p, rule.points) {
  weights_ = rule.weights;
}

void ElementSampling::check_nodes(const Eigen::Matrix2Xd& X) const {
  if (X.cols() != node_count()) {
    throw Error("element of order " + std::to_string(p_) + " needs " +
                std::to_string(node_count()) + " nodes, got " + std::to_string(X.cols()));
  }
}

}  // namespace homesh
