#pragma once
// The measures of W built from the inverse or the condition of W or of its
// metric tensor D = W^T W (Eq 3.14): Q6 smoothness, Q7 aspect ratio, Q9 and
// Q10 their "non-dimensional" variants, Q11 and Q16 condition numbers, Q8 the
// Oddy shape measure. W (2 by 2) is the ideal -> physical Jacobian
// (quality/ideal_jacobian.h), omega = det W, norms are Frobenius norms. The
// *_raw functions are the Table 3.1 formulas (meaningful for omega > 0); the
// *_quality functions are in [0, 1], 1 at W = I, 0 for omega <= 0.
//
// 2D identities (Section 3.7.3): omega |W^-1|_F^2 = |W|_F^2 / omega =
// |W|_F |W^-1|_F, so raw Q6 = Q7 = Q11 <= 1/2 (and = Q12 / 2,
// branets_carey_measures.h); normalised as 2 raw they are equal and
// scale-invariant, 1 exactly at W = s R.
//
// Q9, Q10 (Eq 3.43) keep the thesis's exponent 2/3, which is Knupp's 2/d for
// tetrahedra (d = 3). Applied in 2D it leaves them scale-sensitive (Q9 raw
// ~ s^(2/3), Q10 raw ~ s^(-2/3) under W -> s W), which is what Table 3.7
// records; the dimension-generic 2/d, d = 2, would collapse both onto Q6. In
// 2D raw Q9 = raw Q6 omega^(1/3) and raw Q10 = raw Q7 omega^(-1/3).
//
// Q8 (Oddy et al. 1988 in Knupp's matrix-norm form, Eq 3.42) is
// [3/2 omega^(-4/d) (|D|_F^2 - 1/3 |W|_F^4)]^-1 with d = 2. The constants 3/2
// and 1/3 are the d = 3 ones (Knupp's generic form is
// (|D|_F^2 - |W|_F^4 / d) / omega^(4/d), zero at the ideal); we keep the
// thesis's mix because it is what makes its stated 2D relation exact: with
// t = sigma_1^2 / sigma_2^2 (singular values of W), 1 / raw Q8 = t + 1/t - 1
// and 1 / raw Q16 = t + 1/t, so 1/Q16 - 1/Q8 = 1 ("Q16 - Q8 = 1"), and after
// normalisation Theta8 = 2 Theta16 (Eq 3.49): Q8 and Q16 detect distortion
// identically. (The generic 1/d = 1/2 would make normalised Q8 equal Q16.)
#include <Eigen/Core>

namespace homesh {

/// Q6 raw, smoothness (Brackbill & Saltzman; Eq 3.40): (omega |W^-1|_F^2)^-1, at most 1/2.
double smoothness_raw(const Eigen::Matrix2d& W);
/// Q6: 2 (omega |W^-1|_F^2)^-1 = 2 omega / |W|_F^2.
double smoothness_quality(const Eigen::Matrix2d& W);

/// Q7 raw, aspect ratio (Tinoco-Ruiz & Barrera-Sanchez; Eq 3.41): (|W|_F^2 / omega)^-1, at most
/// 1/2.
double aspect_ratio_raw(const Eigen::Matrix2d& W);
/// Q7: 2 omega / |W|_F^2.
double aspect_ratio_quality(const Eigen::Matrix2d& W);

/// Q8 raw, shape (Oddy et al.; Eq 3.42, d = 2): [3/2 omega^-2 (|D|_F^2 - |W|_F^4 / 3)]^-1, in (0,
/// 1].
double oddy_raw(const Eigen::Matrix2d& W);
/// Q8: the raw value.
double oddy_quality(const Eigen::Matrix2d& W);

/// Q9 raw, non-dimensional smoothness (Knupp; Eq 3.43): (omega^(2/3) |W^-1|_F^2)^-1; 1/2 at W = I.
double nondimensional_smoothness_raw(const Eigen::Matrix2d& W);
/// Q9: min(x, 1/x), x = 2 raw.
double nondimensional_smoothness_quality(const Eigen::Matrix2d& W);

/// Q10 raw, inverse mean ratio (Liu & Joe; Eq 3.43): (omega^(-2/3) |W|_F^2)^-1; 1/2 at W = I.
double inverse_mean_ratio_raw(const Eigen::Matrix2d& W);
/// Q10: min(x, 1/x), x = 2 raw.
double inverse_mean_ratio_quality(const Eigen::Matrix2d& W);

/// Q11 raw, condition number of W (Freitag & Knupp; Eq 3.44): (|W|_F |W^-1|_F)^-1
/// = |omega| / |W|_F^2 in 2D, at most 1/2.
double condition_number_raw(const Eigen::Matrix2d& W);
/// Q11: 2 raw.
double condition_number_quality(const Eigen::Matrix2d& W);

/// Q16 raw, condition number of D (Eq 3.44): (|D|_F |D^-1|_F)^-1 = omega^2 / |D|_F^2, at most 1/2.
double metric_condition_number_raw(const Eigen::Matrix2d& W);
/// Q16: 2 raw.
double metric_condition_number_quality(const Eigen::Matrix2d& W);

}  // namespace homesh
