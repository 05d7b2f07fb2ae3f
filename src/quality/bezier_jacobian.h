#pragma once
// Bezier coefficients of the Jacobian determinant of a Lagrange triangle
// (Johnen, Remacle, Geuzaine, "Geometrical validity of curvilinear finite
// elements", JCP 233, 2013, Section 3).
//
// For a triangle of order p with nodes X (Gmsh order, element/reference_nodes.h)
// the map x(u, v) is a polynomial of degree p, so
//
//   det J = x_u y_v - x_v y_u
//
// is a polynomial of degree 2(p-1) (a constant, 2 * signed area, for a
// straight-sided element). Its Bernstein coefficients are computed exactly (up
// to rounding) rather than by sampling: the nodes are turned into Bezier
// control points b (degree p), the derivatives have the degree p-1 control
// points p (b_{e+d1} - b_{e+d0}) and p (b_{e+d2} - b_{e+d0}), and the product
// of two Bernstein polynomials of degree q has the coefficients
//
//   (f h)_e = sum_{a+b=e} C(q; a) C(q; b) / C(2q; e) f_a h_b,
//
// with C(q; a) the trinomial coefficient q! / (a0! a1! a2!). Gmsh samples det J
// at the Lagrange nodes of order 2(p-1) and converts; both give the same
// polynomial. The per-order tables are built once and cached (thread-safe).
// Orientation: positive for counter-clockwise elements; a clockwise element
// has det J < 0 (as Gmsh's signed Jacobian for a planar mesh).
#include <Eigen/Core>

namespace homesh {

/// Highest element order accepted by jacobian_determinant_bezier.
constexpr int kMaxBezierJacobianOrder = 20;

/// bezier_size(2(p-1)) Bernstein coefficients (storage of bezier_triangle.h)
/// of det J(u, v) for the order-p triangle with nodes X (2 by (p+1)(p+2)/2,
/// Gmsh order). Throws homesh::Error unless 1 <= p <= kMaxBezierJacobianOrder
/// and X has (p+1)(p+2)/2 columns.
Eigen::VectorXd jacobian_determinant_bezier(const Eigen::Matrix2Xd& X, int p);

}  // namespace homesh
