#pragma once
// Bernstein-Bezier polynomials on the reference triangle (0,0), (1,0), (0,1).
//
// With barycentric coordinates (l0, l1, l2) = (1 - u - v, u, v), a polynomial
// of total degree d is written f = sum_{i+j+k=d} c_ijk B^d_ijk with
//
//   B^d_ijk(u, v) = d! / (i! j! k!) l0^i l1^j l2^k.
//
// The B^d_ijk are >= 0 and sum to 1 on the triangle, so min c <= f <= max c
// there, and the corner coefficients c_d00, c_0d0, c_00d are the values of f
// at the corners 0, 1, 2 (Farin, "Triangular Bernstein-Bezier patches", CAGD 3,
// 1986). Coefficient c_ijk belongs to the domain point (j/d, k/d).
//
// Storage: a vector of bezier_size(d) = (d+1)(d+2)/2 coefficients ordered by k,
// then j: index(j, k) = k (d+1) - k (k-1) / 2 + j. Corner 0 is index 0,
// corner 1 is index d, corner 2 is the last index.
#include <Eigen/Core>

namespace homesh {

/// Number of Bernstein polynomials of degree d >= 0 on a triangle.
inline int bezier_size(int d) { return (d + 1) * (d + 2) / 2; }

/// Storage index of c_ijk (i = d - j - k), for j, k >= 0, j + k <= d.
inline int bezier_index(int d, int j, int k) { return k * (d + 1) - k * (k - 1) / 2 + j; }

/// bezier_size(d) values B^d_ijk(u, v) in storage order.
Eigen::VectorXd bernstein_basis(int d, const Eigen::Vector2d& uv);

/// f(u, v) = sum c_ijk B^d_ijk(u, v) for the bezier_size(d) coefficients c.
double bezier_value(int d, const Eigen::VectorXd& c, const Eigen::Vector2d& uv);

/// bezier_size(d) square matrix T mapping values at `nodes` (2 by bezier_size(d),
/// unisolvent for degree d, in any order) to Bezier coefficients: c = T * f.
/// T is the inverse of the collocation matrix A(m, i) = B_i(nodes.col(m)).
/// Throws homesh::Error if the node count is wrong or the nodes are not unisolvent.
Eigen::MatrixXd lagrange_to_bezier(int d, const Eigen::Matrix2Xd& nodes);

}  // namespace homesh
