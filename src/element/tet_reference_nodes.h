#pragma once
// Nodes of the Lagrange tetrahedron of order p, in Gmsh's ordering, on the
// reference tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1) (issue 24: the first
// piece of 3D).
//
// The 4 corners; the p-1 nodes of each edge 0-1, 1-2, 2-0, 3-0, 3-2, 3-1 (Gmsh's
// MTetrahedron edges), from the edge's first corner to its second; for p >= 3 the
// interior nodes of each face (0,2,1), (0,1,3), (0,3,2), (3,1,2) (Gmsh's faces):
// the nodes of a triangle of order p-3 (element/reference_nodes.h) shifted by
// (1, 1), at face corner 0 + a * (corner 1 - corner 0) / p + b * (corner 2 -
// corner 0) / p for each of its (a, b); for p >= 4 the interior nodes, recursively,
// as a tetrahedron of order p-4 shifted by (1, 1, 1).
//
// Node k sits at (i_k, j_k, l_k) / p for the integers of
// tetrahedron_node_indices(p), computed as i * (1.0 / p): Gmsh's coordinates bit
// for bit (tests/element/gmsh_reference_nodes.txt, p = 1..8).
#include <Eigen/Core>

namespace homesh {

/// 3 by (p+1)(p+2)(p+3)/6 integer coordinates (i, j, l) >= 0, i + j + l <= p, of
/// the tetrahedron's nodes, Gmsh order. Throws homesh::Error if p < 1.
Eigen::Matrix3Xi tetrahedron_node_indices(int p);

/// 3 by (p+1)(p+2)(p+3)/6 reference coordinates (u, v, w) of the tetrahedron's
/// nodes, p >= 1, Gmsh order: column k is tetrahedron_node_indices(p).col(k) * (1.0 / p).
Eigen::Matrix3Xd tetrahedron_nodes(int p);

}  // namespace homesh
