#pragma once
// The measures of W that see size as well as shape, and that the thesis
// normalises by their largest value over the element (text after Eq 3.49):
// the matrix norms Q2 Laplace, Q3 metric tensor, Q5 adjoint (Knupp 2001,
// "Algebraic mesh quality metrics", SIAM J. Sci. Comput. 23(1)) and the
// determinant measures Q4 equal volume, Q17 idealised Jacobian.
//
// W (2 by 2) is the ideal -> physical Jacobian (quality/ideal_jacobian.h),
// omega = det W the ratio of the physical area to that of the unit equilateral
// triangle at the point, D = W^T W (Eq 3.14). The *_raw functions are the
// Table 3.1 formulas (meaningful for omega > 0); the *_quality functions fold
// the ratio to the ideal value with ratio_quality (quality/ratio_quality.h)
// and are 0 for omega <= 0. In 2D |adj W|_F = |W|_F, so Q5 = Q2 (Section
// 3.7.3), and Q4 = Q17^2: Q4 responds faster to the same distortion.
#include <Eigen/Core>

namespace homesh {

/// Q2 raw, Laplace (Eq 3.34): |W|_F^2; 2 at W = I.
double laplace_raw(const Eigen::Matrix2d& W);
/// Q2: min(x, 1/x), x = |W|_F^2 / 2.
double laplace_quality(const Eigen::Matrix2d& W);

/// Q3 raw, metric tensor (Liao; Eq 3.37): |W^T W|_F^2 = |D|_F^2; 2 at W = I.
double metric_tensor_raw(const Eigen::Matrix2d& W);
/// Q3: min(x, 1/x), x = |D|_F^2 / 2.
double metric_tensor_quality(const Eigen::Matrix2d& W);

/// Q4 raw, equal volume (Eq 3.38): omega^2.
double equal_volume_raw(const Eigen::Matrix2d& W);
/// Q4: min(omega^2, 1/omega^2).
double equal_volume_quality(const Eigen::Matrix2d& W);

/// Q5 raw, adjoint (Jacquotte & Cabello; Eq 3.39): |adj W|_F^2; 2 at W = I.
double adjoint_raw(const Eigen::Matrix2d& W);
/// Q5: min(x, 1/x), x = |adj W|_F^2 / 2.
double adjoint_quality(const Eigen::Matrix2d& W);

/// Q17 raw, idealised Jacobian (Eq 3.47): omega = det W.
double idealised_jacobian_raw(const Eigen::Matrix2d& W);
/// Q17: min(omega, 1/omega).
double idealised_jacobian_quality(const Eigen::Matrix2d& W);

}  // namespace homesh
