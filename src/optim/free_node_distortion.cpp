#include "optim/free_node_distortion.h"

#include <string>

#include "core/error.h"
#include "element/quadrature.h"
#include "quality/distortion.h"

namespace homesh {

FreeNodeDistortion::FreeNodeDistortion(const Measure& m, Eigen::Matrix2Xd X, int p,
                                       std::vector<int> free_nodes,
                                       const DistortionSettings& settings)
    : m_(&m),
      nodes_(std::move(X)),
      p_(p),
      free_(std::move(free_nodes)),
      settings_(settings),
      rule_(p, triangle_quadrature(settings.quadrature_degree)) {
  rule_.check_nodes(nodes_);
  for (int k : free_) {
    if (k < 0 || k >= nodes_.cols()) {
      throw Error("free node " + std::to_string(k) + " is not a node of the order-" +
                  std::to_string(p) + " element");
    }
  }
}

Eigen::VectorXd FreeNodeDistortion::coordinates(const Eigen::Matrix2Xd& X) const {
  Eigen::VectorXd x(dimension());
  for (size_t i = 0; i < free_.size(); ++i)
    x.segment<2>(2 * static_cast<Eigen::Index>(i)) = X.col(free_[i]);
  return x;
}

Eigen::Matrix2Xd FreeNodeDistortion::element(const Eigen::VectorXd& x) const {
  Eigen::Matrix2Xd X = nodes_;
  for (size_t i = 0; i < free_.size(); ++i)
    X.col(free_[i]) = x.segment<2>(2 * static_cast<Eigen::Index>(i));
  return X;
}

double FreeNodeDistortion::operator()(const Eigen::VectorXd& x) const {
  return distortion_function(*m_, rule_, element(x), settings_.r, settings_.reference);
}

}  // namespace homesh
