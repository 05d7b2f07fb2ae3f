#pragma once
// Nodes of the complete Lagrange quadrilateral of order p, in Gmsh's ordering,
// on the reference square [0, 1]^2 (Gmsh's own is [-1, 1]^2; this is its image
// under x -> (x + 1) / 2, so that the square's edge 0-1 is the reference line
// [0, 1] of element/reference_nodes.h and the unit square is the ideal element
// of the quality measures: W = J there).
//
// Order (Gmsh's MQuadrangleN, checked against getElementProperties of Gmsh
// 4.8.4 in tests/element/gmsh_reference_nodes.txt): the 4 corners (0,0),
// (1,0), (1,1), (0,1), counter-clockwise; the p-1 nodes of each edge 0-1, 1-2,
// 2-3, 3-0, from the edge's first corner to its second; then the interior
// nodes, recursively, as a quadrilateral of order p-2 whose corners are
// (1/p, 1/p), ((p-1)/p, 1/p), ((p-1)/p, (p-1)/p), (1/p, (p-1)/p) (order 0: the
// single centre node).
//
// Node k sits at (i_k, j_k) / p for the integers of quad_reference_node_indices(p).
#include <Eigen/Core>

namespace homesh {

/// 2 by (p+1)^2 integer coordinates (i, j), 0 <= i, j <= p, of the
/// quadrilateral's nodes, Gmsh order. Throws homesh::Error if p < 1.
Eigen::Matrix2Xi quad_reference_node_indices(int p);

/// 2 by (p+1)^2 reference coordinates (u, v) in [0, 1]^2 of the
/// quadrilateral's nodes, Gmsh order: column k is
/// quad_reference_node_indices(p).col(k) * (1.0 / p).
Eigen::Matrix2Xd quad_reference_nodes(int p);

}  // namespace homesh
