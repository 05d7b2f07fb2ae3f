#include "quality/branets_carey_measures.h"

#include <Eigen/LU>

namespace homesh {

double shape_raw(const Eigen::Matrix2d& W) {
  return W.determinant() / (0.5 * (W.transpose() * W).trace());
}

double shape_quality(const Eigen::Matrix2d& W) {
  if (W.determinant() <= 0.0) return 0.0;
  return shape_raw(W);
}

double dilation_raw(const Eigen::Matrix2d& W) {
  const double omega = W.determinant();
  return 1.0 / (0.5 * (1.0 / omega + omega));
}

double dilation_quality(const Eigen::Matrix2d& W) {
  if (W.determinant() <= 0.0) return 0.0;
  return dilation_raw(W);
}

double shape_dilation_raw(const Eigen::Matrix2d& W, double alpha) {
  return 1.0 / ((1.0 - alpha) / shape_raw(W) + alpha / dilation_raw(W));
}

double shape_dilation_quality(const Eigen::Matrix2d& W, double alpha) {
  if (W.determinant() <= 0.0) return 0.0;
  return shape_dilation_raw(W, alpha);
}

}  // namespace homesh
