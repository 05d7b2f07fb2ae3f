#include "quality/size_measures.h"

#include <Eigen/LU>

#include "quality/ratio_quality.h"

namespace homesh {

double laplace_raw(const Eigen::Matrix2d& W) { return W.squaredNorm(); }

double laplace_quality(const Eigen::Matrix2d& W) {
  if (W.determinant() <= 0.0) return 0.0;
  return ratio_quality(laplace_raw(W), 2.0);
}

double metric_tensor_raw(const Eigen::Matrix2d& W) {
  const Eigen::Matrix2d D = W.transpose() * W;
  return D.squaredNorm();
}

double metric_tensor_quality(const Eigen::Matrix2d& W) {
  if (W.determinant() <= 0.0) return 0.0;
  return ratio_quality(metric_tensor_raw(W), 2.0);
}

double equal_volume_raw(const Eigen::Matrix2d& W) {
  const double omega = W.determinant();
  return omega * omega;
}

double equal_volume_quality(const Eigen::Matrix2d& W) {
  if (W.determinant() <= 0.0) return 0.0;
  return ratio_quality(equal_volume_raw(W), 1.0);
}

double adjoint_raw(const Eigen::Matrix2d& W) {
  Eigen::Matrix2d adj;
  adj << W(1, 1), -W(0, 1), -W(1, 0), W(0, 0);
  return adj.squaredNorm();
}

double adjoint_quality(const Eigen::Matrix2d& W) {
  if (W.determinant() <= 0.0) return 0.0;
  return ratio_quality(adjoint_raw(W), 2.0);
}

double idealised_jacobian_raw(const Eigen::Matrix2d& W) { return W.determinant(); }

double idealised_jacobian_quality(const Eigen::Matrix2d& W) {
  return ratio_quality(idealised_jacobian_raw(W), 1.0);
}

}  // namespace homesh
