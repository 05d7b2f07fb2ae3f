#pragma once
// The thesis' measures (Table 3.1, Eqs 3.33-3.47) on tetrahedra (issue 24): the
// same formulas with d = 3 and W = J inv(J_ri), J_ri the map from the
// reference tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1) to the regular
// tetrahedron of unit edges (the ideal element; thesis Eq 3.5 one dimension up).
//
// Normalisation (Section 3.7), each measure 1 at W = I:
// - the size measures Q2, Q3, Q5 fold x = raw / 3 (their ideal value in 3D),
//   Q4 and Q17 fold omega^2 and omega (ratio_quality.h), as in 2D;
// - Q6 (omega |W^-1|^2)^-1 and Q7 (|W|^2 / omega)^-1 are scale invariant in 2D
//   only: in 3D they scale like 1 / s and s, so they fold x = 3 raw, as the
//   size measures do (a choice: the thesis gives them in 2D);
// - Q9 (omega^(2/3) |W^-1|^2)^-1 and Q10 (omega^(-2/3) |W|^2)^-1 are the 3D
//   forms (the thesis writes them with exponent 2/3): scale invariant in 3D,
//   at most 1/3, so 3 raw; Q11 (|W| |W^-1|)^-1 and Q16 (|D| |D^-1|)^-1 at
//   most 1/3 in 3D, so 3 raw;
// - Q8, Oddy et al.'s (|D|^2 - |W|^4 / d) omega^(-4/d), is 0 at the ideal in
//   any d; the thesis' 2D constants (3/2, 1/3) make its inverse 1 there only in
//   2D, so in 3D homesh takes [1 + 3/2 omega^(-4/3) (|D|^2 - |W|^4 / 3)]^-1
//   (a choice), 1 at the ideal and falling with the distortion;
// - Q12 ([tr D / d]^(d/2) / omega)^-1 with d = 3, Q13 and Q14 as in 2D;
// - Q1, min J / max J over the element, is the same in any dimension.
// Every quality is 0 where omega <= 0.
#include <Eigen/Core>

namespace homesh {

/// inv(J_ri) of the regular tetrahedron of unit edges, corners (0,0,0),
/// (1,0,0), (1/2, sqrt3/2, 0), (1/2, sqrt3/6, sqrt(2/3)).
const Eigen::Matrix3d& regular_tetrahedron_inverse();

/// The raw value (Table 3.1's formula with d = 3) and the normalised quality
/// of measure Q<number> at W, for number in 2..17 but 1 and 15; the functions
/// the measure registry's raw3 and quality3 point to.
double laplace_raw3(const Eigen::Matrix3d& W);
double laplace_quality3(const Eigen::Matrix3d& W);
double metric_tensor_raw3(const Eigen::Matrix3d& W);
double metric_tensor_quality3(const Eigen::Matrix3d& W);
double equal_volume_raw3(const Eigen::Matrix3d& W);
double equal_volume_quality3(const Eigen::Matrix3d& W);
double adjoint_raw3(const Eigen::Matrix3d& W);
double adjoint_quality3(const Eigen::Matrix3d& W);
double smoothness_raw3(const Eigen::Matrix3d& W);
double smoothness_quality3(const Eigen::Matrix3d& W);
double aspect_ratio_raw3(const Eigen::Matrix3d& W);
double aspect_ratio_quality3(const Eigen::Matrix3d& W);
double oddy_raw3(const Eigen::Matrix3d& W);
double oddy_quality3(const Eigen::Matrix3d& W);
double nondimensional_smoothness_raw3(const Eigen::Matrix3d& W);
double nondimensional_smoothness_quality3(const Eigen::Matrix3d& W);
double inverse_mean_ratio_raw3(const Eigen::Matrix3d& W);
double inverse_mean_ratio_quality3(const Eigen::Matrix3d& W);
double condition_number_raw3(const Eigen::Matrix3d& W);
double condition_number_quality3(const Eigen::Matrix3d& W);
double shape_raw3(const Eigen::Matrix3d& W);
double shape_quality3(const Eigen::Matrix3d& W);
double dilation_raw3(const Eigen::Matrix3d& W);
double dilation_quality3(const Eigen::Matrix3d& W);
double shape_dilation_raw3(const Eigen::Matrix3d& W);
double shape_dilation_quality3(const Eigen::Matrix3d& W);
double metric_condition_number_raw3(const Eigen::Matrix3d& W);
double metric_condition_number_quality3(const Eigen::Matrix3d& W);
double idealised_jacobian_raw3(const Eigen::Matrix3d& W);
double idealised_jacobian_quality3(const Eigen::Matrix3d& W);

}  // namespace homesh
