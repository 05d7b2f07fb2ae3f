#pragma once
// Quadrature on the reference triangle (0,0), (1,0), (0,1) and on the line [0, 1].
#include <Eigen/Core>

#include "element/gauss_jacobi.h"

namespace homesh {

/// Points (2 by n, inside the triangle) and weights (n, summing to the area 1/2).
struct QuadratureRule {
  Eigen::Matrix2Xd points;
  Eigen::VectorXd weights;
};

/// A rule with positive weights and points strictly inside the triangle,
/// integrating every polynomial of total degree <= `degree` (>= 0) exactly.
///
/// Conical product (Stroud 1971, "Approximate calculation of multiple
/// integrals", Sec 2.7): with the collapsed coordinates (u, v) = (s (1 - t), t),
/// du dv = (1 - t) ds dt, so
///   int_T f du dv = int_0^1 int_0^1 f(s (1 - t), t) (1 - t) ds dt,
/// integrated by the n-point Gauss-Legendre rule in s and the n-point
/// Gauss-Jacobi rule of weight (1 - t) in t, n = floor(degree / 2) + 1: u^a v^b
/// becomes s^a (1 - t)^a t^b, of degree <= degree in s and in t. n^2 points.
QuadratureRule triangle_quadrature(int degree);

/// Points (3 by n, inside the tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1))
/// and weights (n, summing to the volume 1/6).
struct TetQuadratureRule {
  Eigen::Matrix3Xd points;
  Eigen::VectorXd weights;
};

/// A rule with positive weights and points strictly inside the tetrahedron,
/// integrating every polynomial of total degree <= `degree` (>= 0) exactly.
///
/// The conical product of triangle_quadrature one dimension up (Stroud 1971,
/// Sec 2.7): (u, v, w) = (r (1 - s) (1 - t), s (1 - t), t), du dv dw =
/// (1 - s) (1 - t)^2 dr ds dt, integrated by n-point Gauss-Legendre in r,
/// Gauss-Jacobi of weight (1 - s) in s and of weight (1 - t)^2 in t,
/// n = floor(degree / 2) + 1. n^3 points.
TetQuadratureRule tetrahedron_quadrature(int degree);

/// Gauss-Legendre rule on [0, 1] exact to `degree` (>= 0): floor(degree / 2) + 1
/// increasing points, positive weights summing to 1.
LineQuadratureRule line_quadrature(int degree);

}  // namespace homesh
