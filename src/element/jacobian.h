#pragma once
// The Jacobian of the map from the reference triangle to a physical element
// (thesis Eq 3.3): J = dx/d(u,v) = X * dN^T, with X the 2 by n node coordinates
// and dN the 2 by n basis derivatives at the point. Eigen/LU comes with it for
// J.determinant(), the thesis' |J|.
#include <Eigen/Core>
#include <Eigen/LU>

namespace homesh {

/// J (2 by 2) at a point, from node coordinates X (2 by n) and the basis
/// gradients dN (2 by n, rows d/du and d/dv) at that point.
inline Eigen::Matrix2d jacobian(const Eigen::Matrix2Xd& X, const Eigen::Matrix2Xd& dN) {
  return X * dN.transpose();
}

}  // namespace homesh
