#pragma once
// The integer barycentric coordinates of the nodes of the Lagrange line,
// triangle and tetrahedron of order p, Gmsh order: node k sits at the
// combination of the corners with weights column k / p.
#include <Eigen/Core>

namespace homesh {

/// corners (2: line, 3: triangle, 4: tetrahedron) by #nodes non-negative integers
/// summing to p per column: the weights times p of each corner at each node
/// (element/reference_nodes.h, element/tet_reference_nodes.h). Throws
/// homesh::Error if p < 1 or corners is not 2, 3 or 4.
Eigen::MatrixXi barycentric_indices(int corners, int p);

}  // namespace homesh
