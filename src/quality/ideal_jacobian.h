#pragma once
// The Jacobian W of the map from the ideal element to the physical one
// (thesis Eq 3.5, composite map phi_r->p = phi_i->p o phi_r->i):
//
//   W = J * inv(J_ri),
//
// with J the Jacobian of the reference -> physical map (Eq 3.3,
// element/jacobian.h) and J_ri the constant Jacobian of the affine map from the
// reference triangle (0,0), (1,0), (0,1) to the equilateral triangle of the
// same base (0,0), (1,0), (1/2, sqrt(3)/2):
//
//   J_ri = [1  1/2      ]     inv(J_ri) = [1  -1/sqrt(3)]
//          [0  sqrt(3)/2],                [0   2/sqrt(3)].
//
// W = I exactly when the element is the equilateral triangle of side 1 with
// the corner order of the reference triangle; W = s R (R a rotation) for any
// equilateral triangle of side s. So the side length 1 is the target size of
// the scale-sensitive measures: to target size h, pass W / h.
#include <Eigen/Core>

namespace homesh {

/// J_ri (2 by 2): reference triangle -> unit equilateral triangle.
inline Eigen::Matrix2d reference_to_ideal_jacobian() {
  Eigen::Matrix2d J_ri;
  J_ri << 1.0, 0.5, 0.0, 0.8660254037844386;  // sqrt(3)/2
  return J_ri;
}

/// W = J inv(J_ri) (2 by 2) from the reference -> physical Jacobian J (2 by 2).
inline Eigen::Matrix2d ideal_jacobian(const Eigen::Matrix2d& J) {
  constexpr double kInvSqrt3 = 0.5773502691896258;  // 1/sqrt(3)
  Eigen::Matrix2d inv_J_ri;
  inv_J_ri << 1.0, -kInvSqrt3, 0.0, 2.0 * kInvSqrt3;
  return J * inv_J_ri;
}

}  // namespace homesh
