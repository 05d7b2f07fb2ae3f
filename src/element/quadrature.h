#pragma once
// Quadrature on the reference triangle (0,0), (1,0), (0,1).
#include <Eigen/Core>

namespace homesh {

/// Points (2 by n, inside the triangle) and weights (n, summing to the area 1/2).
struct QuadratureRule {
  Eigen::Matrix2Xd points;
  Eigen::VectorXd weights;
};

/// A rule with positive weights integrating every polynomial of total degree
/// <= `degree` exactly (degree >= 0).
QuadratureRule triangle_quadrature(int degree);

/// Gauss-Legendre rule on [0, 1] exact to `degree`: points and weights summing to 1.
QuadratureRule line_quadrature(int degree);

}  // namespace homesh
