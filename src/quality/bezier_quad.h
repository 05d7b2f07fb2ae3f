#pragma once
// Tensor-product Bernstein-Bezier polynomials on the reference square [0, 1]^2.
//
// A polynomial of degree m in u and n in v is written
//
//   f(u, v) = sum_{i=0..m} sum_{j=0..n} c_ij B^m_i(u) B^n_j(v),
//   B^m_i(t) = C(m, i) t^i (1 - t)^(m-i).
//
// The products B^m_i B^n_j are >= 0 and sum to 1 on the square, so
// min c <= f <= max c there, and the corner coefficients c_00, c_m0, c_mn,
// c_0n are the values of f at the corners (0,0), (1,0), (1,1), (0,1) (Farin,
// "Curves and surfaces for CAGD", Ch 16). Coefficient c_ij belongs to the
// domain point (i/m, j/n).
//
// Storage: a vector of (m+1)(n+1) coefficients, u fastest:
// index(i, j) = j (m+1) + i.
#include <Eigen/Core>

namespace homesh {

/// Number of tensor-product Bernstein polynomials of degrees (m, n).
inline int quad_bezier_size(int m, int n) { return (m + 1) * (n + 1); }

/// Storage index of c_ij for degrees (m, n).
inline int quad_bezier_index(int m, int i, int j) { return j * (m + 1) + i; }

/// (m+1)(n+1) values B^m_i(u) B^n_j(v) in storage order; m, n >= 0.
Eigen::VectorXd quad_bernstein_basis(int m, int n, const Eigen::Vector2d& uv);

/// p+1 square matrix T mapping the values of a degree-p polynomial of one
/// variable at t = 0, 1/p, ..., 1 (p >= 1) to its Bernstein coefficients:
/// c = T f. T is the inverse of A(k, i) = B^p_i(k / p).
Eigen::MatrixXd line_lagrange_to_bezier(int p);

/// Coefficients of the polynomial of degrees (d, d) with coefficients `c`
/// ((d+1)^2) on the four half-size squares, counter-clockwise from the
/// origin: column s of `sub` ((d+1)^2 by 4) receives those on
///   S0 = [0, 1/2]^2, S1 = [1/2, 1] x [0, 1/2], S2 = [1/2, 1]^2, S3 = [0, 1/2] x [1/2, 1],
/// each mapped from [0, 1]^2 without turning. De Casteljau's algorithm at 1/2
/// in u, then in v: each sub-coefficient is a convex combination of the
/// coefficients c, so the bounds tighten under subdivision. `sub` must not
/// alias `c`; d <= 63. Costs O(d^3) operations.
void quad_bezier_subdivide(int d, const Eigen::Ref<const Eigen::VectorXd>& c,
                           Eigen::Ref<Eigen::MatrixXd> sub);

}  // namespace homesh
