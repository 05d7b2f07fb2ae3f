#pragma once
// Nodes of the Lagrange triangle of order p on the reference triangle
// (0,0), (1,0), (0,1), in Gmsh's ordering: 3 corners; p-1 nodes on each edge
// 0-1, 1-2, 2-0, from the edge's first corner to its second; then the interior
// nodes, recursively, as a triangle of order p-3 whose corners are
// (1/p, 1/p), ((p-2)/p, 1/p), (1/p, (p-2)/p).
#include <Eigen/Core>

namespace homesh {

/// 2 by (p+1)(p+2)/2 reference coordinates (u, v) of the nodes, p >= 1.
Eigen::Matrix2Xd reference_nodes(int p);

/// 1 by p+1 reference coordinates in [0, 1] of the nodes of a line of order p,
/// Gmsh order: the two ends, then the interior nodes from 0 to 1.
Eigen::RowVectorXd reference_line_nodes(int p);

}  // namespace homesh
