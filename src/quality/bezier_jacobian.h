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

/// Highest element order accepted by the functions below.
constexpr int kMaxBezierJacobianOrder = 20;
/// Nodes of a triangle of that order, (p+1)(p+2)/2.
constexpr int kMaxBezierJacobianNodes =
    (kMaxBezierJacobianOrder + 1) * (kMaxBezierJacobianOrder + 2) / 2;

/// Control points of one derivative: 2 by bezier_size(p-1), stored in place
/// (no heap allocation) for every order accepted.
using JacobianControlPoints =
    Eigen::Matrix<double, 2, Eigen::Dynamic, 0, 2, kMaxBezierJacobianNodes>;

/// bezier_size(2(p-1)) Bernstein coefficients (storage of bezier_triangle.h)
/// of det J(u, v) for the order-p triangle with nodes X (2 by (p+1)(p+2)/2,
/// Gmsh order). Throws homesh::Error unless 1 <= p <= kMaxBezierJacobianOrder
/// and X has (p+1)(p+2)/2 columns.
Eigen::VectorXd jacobian_determinant_bezier(const Eigen::Matrix2Xd& X, int p);

/// The Bezier control points of the columns of J, degree p-1, without the
/// factor p: x_u = p sum_e U.col(e) B^{p-1}_e(u, v) and likewise x_v with V;
/// U, V are 2 by bezier_size(p-1). Everything else that needs J of the element
/// (det J's coefficients, J at sample points) can start from them. No heap
/// allocation. Throws as above, and if U or V has the wrong size.
void jacobian_control_points(const Eigen::Matrix2Xd& X, int p, Eigen::Ref<Eigen::Matrix2Xd> U,
                             Eigen::Ref<Eigen::Matrix2Xd> V);

/// det J's coefficients (as above) from the control points U, V of the order-p
/// element, written to c (bezier_size(2(p-1))). No heap allocation.
void jacobian_determinant_bezier(const Eigen::Ref<const Eigen::Matrix2Xd>& U,
                                 const Eigen::Ref<const Eigen::Matrix2Xd>& V, int p,
                                 Eigen::Ref<Eigen::VectorXd> c);

}  // namespace homesh
