#pragma once
// Shape, dilation and combined measures of Branets & Carey (2005, "A local cell
// quality metric and variational grid smoothing algorithm", Eng. Comput. 21),
// thesis Eq 3.45, of W, the ideal -> physical Jacobian
// (quality/ideal_jacobian.h), omega = det W, d = 2.
//
// The extracted Eq 3.45 reads "Q12 = 1/omega [1/d tr(W^T W)]^(d/2 - 1)": the
// trailing -1 is the outer inverse every row of Table 3.1 carries, as
// Branets & Carey's shape metric beta = [tr(W^T W) / d]^(d/2) / omega >= 1
// (1 iff W = s R) shows; so Q12 = beta^-1 = 2 omega / |W|_F^2 in 2D, exactly
// twice raw Q6 = Q7 = Q11 (the thesis: "half of Q12 is equal to Q6, Q7 and
// Q11"), and equal to them once those are normalised. Likewise in
// "Q14 = [(1 - alpha) Q12 + alpha Q13]^-1" Q12 and Q13 stand for the metrics
// beta and mu before inversion. The dilation target V is the area of the ideal
// element; W is relative to the unit equilateral triangle, so V = 1 (to target
// another size, scale W). All three are in (0, 1], 1 at the ideal, 0 for
// omega <= 0, and equal their raw values (no further normalisation).
#include <Eigen/Core>

namespace homesh {

/// Weight of the dilation in Q14 used by the registry (thesis Fig 3.24).
constexpr double kCombinedAlpha = 0.5;

/// Q12, shape (Eq 3.45): ([tr(W^T W) / 2] / omega)^-1 = 2 omega / |W|_F^2.
double shape_raw(const Eigen::Matrix2d& W);
/// Q12 for omega > 0, else 0.
double shape_quality(const Eigen::Matrix2d& W);

/// Q13, dilation (Eq 3.45): [1/2 (V / omega + omega / V)]^-1, V = 1.
double dilation_raw(const Eigen::Matrix2d& W);
/// Q13 = 2 omega / (1 + omega^2) for omega > 0, else 0.
double dilation_quality(const Eigen::Matrix2d& W);

/// Q14, shape and dilation (Eq 3.45): [(1 - alpha) / Q12 + alpha / Q13]^-1,
/// 0 <= alpha <= 1 (the weighted harmonic mean of Q12 and Q13).
double shape_dilation_raw(const Eigen::Matrix2d& W, double alpha = kCombinedAlpha);
/// Q14 for omega > 0, else 0.
double shape_dilation_quality(const Eigen::Matrix2d& W, double alpha = kCombinedAlpha);

}  // namespace homesh
