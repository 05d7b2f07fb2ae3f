#pragma once
// The ideal element of the thesis's interior regions (Section 3.7.1): the
// equilateral triangle of side 1, with its high-order nodes where the affine
// map puts them. Its W (quality/ideal_jacobian.h) is the identity, so every
// measure is 1 and the distortion function 0 on it: the optimum that the
// searches of Section 3.8.2 must find, and the starting point of the boundary
// cases of Section 3.8.3.
#include <Eigen/Core>

namespace homesh {

/// Nodes (2 by (p+1)(p+2)/2, Gmsh order) of the order-p triangle with corners
/// (0,0), (1,0), (1/2, sqrt(3)/2) and straight edges. Throws homesh::Error if p < 1.
Eigen::Matrix2Xd equilateral_element(int p);

}  // namespace homesh
