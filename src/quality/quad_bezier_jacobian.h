#pragma once
// Bezier coefficients of the Jacobian determinant of a Lagrange quadrilateral
// on the tensor-product Bernstein basis (Johnen, Remacle, Geuzaine,
// "Geometrical validity of curvilinear finite elements", JCP 233, 2013,
// Section 3; Gmsh's JacobianBasis for TYPE_QUA).
//
// A complete quadrilateral of order p with nodes X (Gmsh order,
// element/quad_reference_nodes.h) maps the square [0, 1]^2 by a polynomial of
// degree p in u and p in v, so x_u has degrees (p-1, p), x_v degrees (p, p-1) and
//
//   det J = x_u y_v - x_v y_u
//
// degrees (2p-1, 2p-1): (2p)^2 coefficients (4 for a bilinear quadrilateral,
// whose det J is bilinear, not constant). They are computed exactly (up to
// rounding): the nodes become the Bezier control points b_ij (degree p, the
// 1D Lagrange -> Bernstein map in each variable), the derivatives have control
// points p (b_{i+1,j} - b_ij) and p (b_{i,j+1} - b_ij), and the product of
// Bernstein polynomials of degrees (m1, n1) and (m2, n2) has coefficients
//
//   (f h)_kl = sum_{i+i'=k, j+j'=l} C(m1,i) C(m2,i') / C(m1+m2,k)
//                                   C(n1,j) C(n2,j') / C(n1+n2,l) f_ij h_i'j'.
//
// Gmsh samples det J at the Lagrange points of the same space and converts;
// both give the same polynomial. Tables per order are built once (thread-safe).
// Orientation: positive for counter-clockwise elements. The reference square
// is [0, 1]^2 (Gmsh's is [-1, 1]^2: its det J is this one / 4; minJ/maxJ is
// the same).
#include <Eigen/Core>

#include "quality/bezier_jacobian.h"

namespace homesh {

/// (2p)^2 Bernstein coefficients (storage of bezier_quad.h, degrees
/// (2p-1, 2p-1)) of det J(u, v) of the order-p quadrilateral with nodes X
/// (2 by (p+1)^2, Gmsh order). Throws homesh::Error unless
/// 1 <= p <= kMaxBezierJacobianOrder and X has (p+1)^2 columns.
Eigen::VectorXd quad_jacobian_determinant_bezier(const Eigen::Matrix2Xd& X, int p);

}  // namespace homesh
