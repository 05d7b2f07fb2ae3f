#pragma once
// det J of a Lagrange tetrahedron of order p (nodes in Gmsh order,
// element/tet_reference_nodes.h) in the Bernstein basis of degree 3 (p - 1)
// (quality/bezier_tetrahedron.h): each entry of J = sum_k x_k grad N_k^T is of degree
// p - 1, so det J is of degree 3 (p - 1), interpolated exactly from its values at
// that degree's lattice. For a straight-sided tetrahedron det J = 6 * volume.
#include <Eigen/Core>

namespace homesh {

/// Highest tetrahedron order whose det J bounds homesh computes (degree 12).
constexpr int kMaxTetJacobianOrder = 5;

/// The tetrahedron_bezier_size(3 (p - 1)) Bernstein coefficients of det J of the
/// tetrahedron with nodes X (3 by (p+1)(p+2)(p+3)/6). Throws homesh::Error if p is
/// out of 1..kMaxTetJacobianOrder, X has the wrong size or a non-finite entry.
Eigen::VectorXd tetrahedron_jacobian_bezier(const Eigen::Matrix3Xd& X, int p);

}  // namespace homesh
