#pragma once
// VTK's node order of its Lagrange triangle and curve (VTK_LAGRANGE_TRIANGLE =
// 69, VTK_LAGRANGE_CURVE = 68), and the map from Gmsh's order, which homesh's
// Mesh uses (element/reference_nodes.h), to VTK's.
//
// VTK orders a triangle of order p by its barycentric index
// (vtkHigherOrderTriangle::BarycentricIndex, VTK 9.1): the 3 corners, the p-1
// nodes of edges 0-1, 1-2, 2-0 (each from its first corner to its second),
// then the interior nodes recursively as a triangle of order p-3. Node k has
// parametric coordinates (r, s) = (b0, b1) / p of its barycentric index
// (b0, b1, b2), corners (0,0), (1,0), (0,1). A curve lists its 2 end nodes,
// then its p-1 interior nodes from the first end to the second
// (vtkLagrangeCurve). Both happen to be Gmsh's orders: the maps below are
// derived from the two definitions and are the identity for every order, as
// tests/io/vtk_node_order_test.cpp and tests/python/test_vtu.py (against
// VTK's own parametric coordinates) check.
#include <Eigen/Core>
#include <vector>

namespace homesh {

/// 2 by (p+1)(p+2)/2 integer coordinates (i, j) = p (r, s) of VTK's Lagrange
/// triangle nodes of order p >= 1, VTK order. Throws homesh::Error if p < 1.
Eigen::Matrix2Xi vtk_triangle_node_indices(int p);

/// (p+1)(p+2)/2 Gmsh node numbers of a triangle of order p >= 1 in VTK order:
/// VTK node k is Gmsh node map[k] (the node at the same reference position).
std::vector<int> gmsh_to_vtk_triangle(int p);

/// p+1 Gmsh node numbers of a line of order p >= 1 in VTK order: VTK node k is
/// Gmsh node map[k].
std::vector<int> gmsh_to_vtk_line(int p);

}  // namespace homesh
