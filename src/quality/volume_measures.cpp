#include "quality/volume_measures.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "quality/branets_carey_measures.h"
#include "quality/ratio_quality.h"

namespace homesh {
namespace {

// |adj W|_F^2: adj W is the transposed cofactor matrix, columns w1 x w2 ... .
double adjugate_norm2(const Eigen::Matrix3d& W) {
  const Eigen::Vector3d a = W.col(1).cross(W.col(2)), b = W.col(2).cross(W.col(0)),
                        c = W.col(0).cross(W.col(1));
  return a.squaredNorm() + b.squaredNorm() + c.squaredNorm();
}

// |W^-1|_F^2 = |adj W|_F^2 / omega^2.
double inverse_norm2(const Eigen::Matrix3d& W) {
  const double omega = W.determinant();
  return adjugate_norm2(W) / (omega * omega);
}

template <double (*Raw)(const Eigen::Matrix3d&)>
double folded(const Eigen::Matrix3d& W, double ideal) {
  if (W.determinant() <= 0.0) return 0.0;
  return ratio_quality(Raw(W), ideal);
}

template <double (*Raw)(const Eigen::Matrix3d&)>
double scaled(const Eigen::Matrix3d& W, double factor) {
  if (W.determinant() <= 0.0) return 0.0;
  return factor * Raw(W);
}

}  // namespace

const Eigen::Matrix3d& regular_tetrahedron_inverse() {
  static const Eigen::Matrix3d inverse = [] {
    Eigen::Matrix3d J;
    J << 1.0, 0.5, 0.5,  //
        0.0, std::sqrt(3.0) / 2.0, std::sqrt(3.0) / 6.0, 0.0, 0.0, std::sqrt(2.0 / 3.0);
    return Eigen::Matrix3d(J.inverse());
  }();
  return inverse;
}

double laplace_raw3(const Eigen::Matrix3d& W) { return W.squaredNorm(); }
double laplace_quality3(const Eigen::Matrix3d& W) { return folded<laplace_raw3>(W, 3.0); }

double metric_tensor_raw3(const Eigen::Matrix3d& W) { return (W.transpose() * W).squaredNorm(); }
double metric_tensor_quality3(const Eigen::Matrix3d& W) {
  return folded<metric_tensor_raw3>(W, 3.0);
}

double equal_volume_raw3(const Eigen::Matrix3d& W) {
  const double omega = W.determinant();
  return omega * omega;
}
double equal_volume_quality3(const Eigen::Matrix3d& W) { return folded<equal_volume_raw3>(W, 1.0); }

double adjoint_raw3(const Eigen::Matrix3d& W) { return adjugate_norm2(W); }
double adjoint_quality3(const Eigen::Matrix3d& W) { return folded<adjoint_raw3>(W, 3.0); }

double smoothness_raw3(const Eigen::Matrix3d& W) {
  return 1.0 / (W.determinant() * inverse_norm2(W));
}
double smoothness_quality3(const Eigen::Matrix3d& W) {
  return folded<smoothness_raw3>(W, 1.0 / 3.0);
}

double aspect_ratio_raw3(const Eigen::Matrix3d& W) { return W.determinant() / W.squaredNorm(); }
double aspect_ratio_quality3(const Eigen::Matrix3d& W) {
  return folded<aspect_ratio_raw3>(W, 1.0 / 3.0);
}

double oddy_raw3(const Eigen::Matrix3d& W) {
  const double omega = W.determinant(), w2 = W.squaredNorm();
  const double f = (W.transpose() * W).squaredNorm() - w2 * w2 / 3.0;
  return 1.0 / (1.0 + 1.5 * f / std::cbrt(omega * omega * omega * omega));
}
double oddy_quality3(const Eigen::Matrix3d& W) { return scaled<oddy_raw3>(W, 1.0); }

double nondimensional_smoothness_raw3(const Eigen::Matrix3d& W) {
  const double omega = W.determinant();
  return 1.0 / (std::cbrt(omega * omega) * inverse_norm2(W));
}
double nondimensional_smoothness_quality3(const Eigen::Matrix3d& W) {
  return scaled<nondimensional_smoothness_raw3>(W, 3.0);
}

double inverse_mean_ratio_raw3(const Eigen::Matrix3d& W) {
  const double omega = W.determinant();
  return std::cbrt(omega * omega) / W.squaredNorm();
}
double inverse_mean_ratio_quality3(const Eigen::Matrix3d& W) {
  return scaled<inverse_mean_ratio_raw3>(W, 3.0);
}

double condition_number_raw3(const Eigen::Matrix3d& W) {
  return 1.0 / std::sqrt(W.squaredNorm() * inverse_norm2(W));
}
double condition_number_quality3(const Eigen::Matrix3d& W) {
  return scaled<condition_number_raw3>(W, 3.0);
}

double shape_raw3(const Eigen::Matrix3d& W) {
  const double t = (W.transpose() * W).trace() / 3.0;
  return W.determinant() / (t * std::sqrt(t));
}
double shape_quality3(const Eigen::Matrix3d& W) { return scaled<shape_raw3>(W, 1.0); }

double dilation_raw3(const Eigen::Matrix3d& W) {
  const double omega = W.determinant();
  return 1.0 / (0.5 * (1.0 / omega + omega));
}
double dilation_quality3(const Eigen::Matrix3d& W) { return scaled<dilation_raw3>(W, 1.0); }

double shape_dilation_raw3(const Eigen::Matrix3d& W) {
  return 1.0 / ((1.0 - kCombinedAlpha) / shape_raw3(W) + kCombinedAlpha / dilation_raw3(W));
}
double shape_dilation_quality3(const Eigen::Matrix3d& W) {
  return scaled<shape_dilation_raw3>(W, 1.0);
}

double metric_condition_number_raw3(const Eigen::Matrix3d& W) {
  const Eigen::Matrix3d D = W.transpose() * W;
  return 1.0 / std::sqrt(D.squaredNorm() * D.inverse().squaredNorm());
}
double metric_condition_number_quality3(const Eigen::Matrix3d& W) {
  return scaled<metric_condition_number_raw3>(W, 3.0);
}

double idealised_jacobian_raw3(const Eigen::Matrix3d& W) { return W.determinant(); }
double idealised_jacobian_quality3(const Eigen::Matrix3d& W) {
  return folded<idealised_jacobian_raw3>(W, 1.0);
}

}  // namespace homesh
