#pragma once
// Nodes of the Lagrange triangle and line of order p, in Gmsh's ordering.
//
// Triangle, on the reference triangle (0,0), (1,0), (0,1): the 3 corners; the
// p-1 nodes of each edge 0-1, 1-2, 2-0, from the edge's first corner to its
// second; then the interior nodes, recursively, as a triangle of order p-3
// whose corners are (1/p, 1/p), ((p-2)/p, 1/p), (1/p, (p-2)/p).
//
// Node k sits at (i_k, j_k) / p for the integers of reference_node_indices(p).
// The coordinates are computed as Gmsh computes them, i * (1.0 / p), so they
// equal Gmsh's bit for bit (tests/element/gmsh_reference_nodes.txt).
#include <Eigen/Core>

namespace homesh {

/// 2 by (p+1)(p+2)/2 integer coordinates (i, j), i, j >= 0, i + j <= p, of the
/// triangle's nodes, Gmsh order (Gmsh calls them the element's "monomials").
/// Throws homesh::Error if p < 1.
Eigen::Matrix2Xi reference_node_indices(int p);

/// 2 by (p+1)(p+2)/2 reference coordinates (u, v) of the triangle's nodes,
/// p >= 1, Gmsh order: column k is reference_node_indices(p).col(k) * (1.0 / p).
Eigen::Matrix2Xd reference_nodes(int p);

/// 1 by p+1 reference coordinates in [0, 1] of the nodes of a line of order p,
/// Gmsh order: the two ends, then the interior nodes from 0 to 1. Gmsh's line
/// lives on [-1, 1]; this is its image under x -> (x + 1) / 2, computed as
/// i * (1.0 / p) so that it equals the u coordinates of the triangle's edge 0-1
/// exactly.
Eigen::RowVectorXd reference_line_nodes(int p);

}  // namespace homesh
