#pragma once
// The linear triangle quality of thesis Eq 4.17 (adopted there from Frey and
// George): twice the ratio of the inscribed to the circumscribed radius,
//
//   Q = 8 (p - a)(p - b)(p - c) / (a b c),   p = (a + b + c) / 2,
//
// a, b, c the edge lengths and p the half-perimeter. Q = 2 r / R is 1 for the
// equilateral triangle, 0 for a degenerate one, and in (0, 1) otherwise; it is
// invariant to translation, rotation, scaling and node order, and blind to
// orientation (an inverted triangle scores as its mirror image).
#include <Eigen/Core>

#include "core/mesh.h"

namespace homesh {

/// Q of Eq 4.17 of the straight triangle with corners X (2 by 3); 0 if an edge
/// has zero length.
double radius_ratio(const Eigen::Matrix<double, 2, 3>& X);

/// #2D elements: Q of Eq 4.17 of every triangle of m, from its three corners; of a
/// quadrilateral (which Eq 4.17 does not define), the least Q of the four triangles
/// of its corners, each corner with its two neighbours (0 if it is not convex).
Eigen::VectorXd radius_ratios(const Mesh& m);

}  // namespace homesh
