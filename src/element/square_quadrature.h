#pragma once
// Quadrature on the reference square [0, 1]^2 of the quadrilaterals
// (element/quad_reference_nodes.h).
#include <Eigen/Core>

#include "element/quadrature.h"

namespace homesh {

/// The tensor product of line_quadrature(degree) with itself: n^2 points,
/// n = floor(degree / 2) + 1, strictly inside the square, positive weights
/// summing to its area 1, integrating exactly every u^a v^b with a <= degree
/// and b <= degree (degree per variable, as the quadrilateral basis is of
/// degree p in u and in v). Point (i, j) (u_i, v_j) is column i + n j.
/// Throws homesh::Error if degree < 0.
QuadratureRule square_quadrature(int degree);

}  // namespace homesh
