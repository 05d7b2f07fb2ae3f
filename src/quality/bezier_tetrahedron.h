#pragma once
// Polynomials of degree d on the reference tetrahedron (0,0,0), (1,0,0), (0,1,0),
// (0,0,1) in the Bernstein basis, for the certified bounds of a tetrahedron's
// det J (quality/jacobian_bounds.h; Johnen, Remacle & Geuzaine, JCP 233, 2013, as
// in 2D): with barycentric (l0, l1, l2, l3) = (1 - u - v - w, u, v, w),
//
//   B_(i,j,l)(u, v, w) = d! / (i! j! l! m!) u^i v^j w^l l0^m,   m = d - i - j - l,
//
// coefficient k at the multi-index tetrahedron_bezier_indices(d).col(k): (0,0,0),
// then i + j + l growing (the coefficients at (0,0,0), (d,0,0), (0,d,0) and (0,0,d)
// are the polynomial's values at the corners). The coefficients come from the
// values at the lattice points (i, j, l) / d by the inverse of the collocation
// matrix, and those of the 8 sub-tetrahedra of the midpoint split (the 4 at the
// corners and the octahedron's 4 round its diagonal between the midpoints of
// edges 0-2 and 1-3) by matrices made the same way, once per degree, from the
// parent's values at each child's lattice. Degrees up to kMaxTetBezierDegree: det J
// of tetrahedra up to p = 5 (d = 3 (p - 1)).
#include <Eigen/Core>

namespace homesh {

constexpr int kMaxTetBezierDegree = 12;

/// Number of Bernstein coefficients of degree d: (d+1)(d+2)(d+3)/6.
constexpr int tetrahedron_bezier_size(int d) { return (d + 1) * (d + 2) * (d + 3) / 6; }

/// 3 by tetrahedron_bezier_size(d) multi-indices (i, j, l) of the coefficients.
Eigen::Matrix3Xi tetrahedron_bezier_indices(int d);

/// The Bernstein coefficients of the degree-d polynomial with the given values at
/// the lattice points tetrahedron_bezier_indices(d) / d. Throws homesh::Error if d
/// is out of 0..kMaxTetBezierDegree or the sizes differ.
Eigen::VectorXd tetrahedron_bezier_from_values(int d, const Eigen::Ref<const Eigen::VectorXd>& f);

/// The value at (u, v, w) of the polynomial with Bernstein coefficients c.
double tetrahedron_bezier_value(int d, const Eigen::Ref<const Eigen::VectorXd>& c,
                                const Eigen::Vector3d& uvw);

/// The coefficients of the 8 children (columns of `sub`, n by 8) of the domain with
/// coefficients c, in the child order above.
void tetrahedron_bezier_subdivide(int d, const Eigen::Ref<const Eigen::VectorXd>& c,
                                  Eigen::Ref<Eigen::MatrixXd> sub);

/// The 4 corners (columns, in the parent's reference coordinates) of child s of the
/// unit reference tetrahedron, 0 <= s < 8.
Eigen::Matrix<double, 3, 4> tetrahedron_child(int s);

}  // namespace homesh
