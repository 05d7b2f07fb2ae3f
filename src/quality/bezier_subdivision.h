#pragma once
// Midpoint subdivision of a Bezier triangle (storage as in bezier_triangle.h).
//
// The reference triangle P0 = (0,0), P1 = (1,0), P2 = (0,1) with edge midpoints
// M01, M12, M20 splits into four sub-triangles, each listed so that its
// vertex m is the image of reference vertex m:
//
//   S0 = (P0, M01, M20):  (u, v) -> (u/2, v/2)
//   S1 = (M01, P1, M12):  (u, v) -> ((1 + u)/2, v/2)
//   S2 = (M20, M12, P2):  (u, v) -> (u/2, (1 + v)/2)
//   S3 = (M12, M20, M01): (u, v) -> ((1 - u)/2, (1 - v)/2)   (the middle one)
//
// The coefficients of f on S_s are the blossom values
// c'_ijk = f[(S_s vertex 0)^i, (S_s vertex 1)^j, (S_s vertex 2)^k] (Farin 1986,
// Section 3; Ramshaw, "Blossoms are polar forms", CAGD 6, 1989). The corner
// sub-triangles are computed by one-dimensional de Casteljau halving along two
// edges (averages only); the middle one from S0 by replacing vertex P0 with
// M12 = M01 + M20 - P0 (an affine, not convex, de Casteljau step). Each
// sub-coefficient is a convex combination of the coefficients c, so the bounds
// min c <= f <= max c tighten under subdivision (Johnen, Remacle, Geuzaine,
// "Geometrical validity of curvilinear finite elements", JCP 233, 2013).
#include <Eigen/Core>

namespace homesh {

/// Coefficients of the degree-d polynomial with coefficients `c`
/// (bezier_size(d)) on the four sub-triangles: column s of `sub`
/// (bezier_size(d) by 4) receives those on S_s. `sub` must not alias `c`.
/// Costs O(d^3) operations.
void bezier_subdivide(int d, const Eigen::Ref<const Eigen::VectorXd>& c,
                      Eigen::Ref<Eigen::MatrixXd> sub);

}  // namespace homesh
