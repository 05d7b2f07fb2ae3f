#include "quality/shape_measures.h"

#include <Eigen/LU>
#include <cmath>

#include "quality/ratio_quality.h"

namespace homesh {

double smoothness_raw(const Eigen::Matrix2d& W) {
  return 1.0 / (W.determinant() * W.inverse().squaredNorm());
}

double smoothness_quality(const Eigen::Matrix2d& W) {
  if (W.determinant() <= 0.0) return 0.0;
  return 2.0 * smoothness_raw(W);
}

double aspect_ratio_raw(const Eigen::Matrix2d& W) { return W.determinant() / W.squaredNorm(); }

double aspect_ratio_quality(const Eigen::Matrix2d& W) {
  if (W.determinant() <= 0.0) return 0.0;
  return 2.0 * aspect_ratio_raw(W);
}

double oddy_raw(const Eigen::Matrix2d& W) {
  const double omega = W.determinant();
  const Eigen::Matrix2d D = W.transpose() * W;
  const double w2 = W.squaredNorm();
  return 1.0 / (1.5 / (omega * omega) * (D.squaredNorm() - w2 * w2 / 3.0));
}

double oddy_quality(const Eigen::Matrix2d& W) {
  if (W.determinant() <= 0.0) return 0.0;
  return oddy_raw(W);
}

double nondimensional_smoothness_raw(const Eigen::Matrix2d& W) {
  return 1.0 / (std::cbrt(W.determinant() * W.determinant()) * W.inverse().squaredNorm());
}

double nondimensional_smoothness_quality(const Eigen::Matrix2d& W) {
  if (W.determinant() <= 0.0) return 0.0;
  return ratio_quality(nondimensional_smoothness_raw(W), 0.5);
}

double inverse_mean_ratio_raw(const Eigen::Matrix2d& W) {
  return std::cbrt(W.determinant() * W.determinant()) / W.squaredNorm();
}

double inverse_mean_ratio_quality(const Eigen::Matrix2d& W) {
  if (W.determinant() <= 0.0) return 0.0;
  return ratio_quality(inverse_mean_ratio_raw(W), 0.5);
}

double condition_number_raw(const Eigen::Matrix2d& W) {
  // In 2D inv(W) = adj(W) / omega and |adj W|_F = |W|_F, so
  // 1 / (|W|_F |W^-1|_F) = |omega| / |W|_F^2: no inverse, no square root.
  return std::abs(W.determinant()) / W.squaredNorm();
}

double condition_number_quality(const Eigen::Matrix2d& W) {
  if (W.determinant() <= 0.0) return 0.0;
  return 2.0 * condition_number_raw(W);
}

double metric_condition_number_raw(const Eigen::Matrix2d& W) {
  // |D^-1|_F = |adj D|_F / det D = |D|_F / omega^2 in 2D; forming D^-1 from D
  // would lose det D = d11 d22 - d12^2 to cancellation when W is ill-conditioned.
  const Eigen::Matrix2d D = W.transpose() * W;
  const double omega = W.determinant();
  return omega * omega / D.squaredNorm();
}

double metric_condition_number_quality(const Eigen::Matrix2d& W) {
  if (W.determinant() <= 0.0) return 0.0;
  return 2.0 * metric_condition_number_raw(W);
}

}  // namespace homesh
