#pragma once
// VTK's node order of its Lagrange triangle (VTK_LAGRANGE_TRIANGLE = 69),
// quadrilateral (VTK_LAGRANGE_QUADRILATERAL = 70) and tetrahedron
// (VTK_LAGRANGE_TETRAHEDRON = 71) and the maps from Gmsh's order, which
// homesh's meshes use (element/reference_nodes.h, element/quad_reference_nodes.h,
// element/tet_reference_nodes.h), to VTK's; the order of a line's nodes along it.
//
// VTK orders a triangle of order p by its barycentric index
// (vtkHigherOrderTriangle::BarycentricIndex, VTK 9.1): the 3 corners, the p-1
// nodes of edges 0-1, 1-2, 2-0 (each from its first corner to its second),
// then the interior nodes recursively as a triangle of order p-3. Node k has
// parametric coordinates (r, s) = (b0, b1) / p of its barycentric index
// (b0, b1, b2), corners (0,0), (1,0), (0,1). That happens to be Gmsh's order:
// the map below is derived from the two definitions and is the identity for
// every order, as tests/io/vtk_node_order_test.cpp (against VTK's own
// parametric coordinates) and tests/python/test_vtu.py check.
//
// VTK orders a tetrahedron of order p by its barycentric index too
// (vtkHigherOrderTetra::BarycentricIndex, VTK 9.1): the 4 corners (0,0,0),
// (1,0,0), (0,1,0), (0,0,1); the p-1 nodes of edges 0-1, 1-2, 2-0, 0-3, 1-3,
// 2-3 (vtkTetra's edges), each from its first corner to its second; for p >= 3
// the interior nodes of faces (0,1,3), (2,3,1), (0,3,2), (0,2,1), each those of
// a triangle of order p-3 in VTK's triangle order shifted by (1, 1), at face
// corner 0 + a * (corner 1 - corner 0) / p + b * (corner 2 - corner 0) / p for
// each of its (a, b); then for p >= 4 the interior nodes, recursively, as a
// tetrahedron of order p-4 shifted by (1, 1, 1). Node k has parametric
// coordinates (r, s, t) = (b0, b1, b2) / p of its barycentric index (b0, b1, b2,
// b3). That is Gmsh's rule (element/tet_reference_nodes.h) with other edges
// and faces: Gmsh's last three edges are 3-0, 3-2, 3-1 where VTK's are 0-3,
// 1-3, 2-3, and its faces are (0,2,1), (0,1,3), (0,3,2), (3,1,2). So from order
// 2 on gmsh_to_vtk_tetrahedron is not the identity: for p = 2 it is the order
// of VTK_QUADRATIC_TETRA (vtkQuadraticTetra), Gmsh's with its last two nodes
// swapped.
//
// Lines are written as VTK_POLY_LINE cells through their nodes in order along
// the line, not as VTK_LAGRANGE_CURVE: VTK 9.1's vtkDataSetSurfaceFilter, and
// so ParaView 5.11, crash (SIGSEGV) on any nonlinear 1D cell (Lagrange curve,
// even VTK_QUADRATIC_EDGE) at a Nonlinear Subdivision Level of 2 or more.
#include <Eigen/Core>
#include <vector>

namespace homesh {

/// 2 by (p+1)(p+2)/2 integer coordinates (i, j) = p (r, s) of VTK's Lagrange
/// triangle nodes of order p >= 1, VTK order. Throws homesh::Error if p < 1.
Eigen::Matrix2Xi vtk_triangle_node_indices(int p);

/// (p+1)(p+2)/2 Gmsh node numbers of a triangle of order p >= 1 in VTK order:
/// VTK node k is Gmsh node map[k] (the node at the same reference position).
std::vector<int> gmsh_to_vtk_triangle(int p);

/// 2 by (p+1)^2 integer coordinates (i, j) = p (r, s) of VTK's Lagrange
/// quadrilateral nodes of order p >= 1 (VTK_LAGRANGE_QUADRILATERAL = 70, VTK
/// 9.1's vtkHigherOrderQuadrilateral::PointIndexFromIJK), VTK order: the
/// corners (0,0), (p,0), (p,p), (0,p); the edge nodes of (0,0)-(p,0),
/// (p,0)-(p,p), (0,p)-(p,p) and (0,0)-(0,p), each with i or j increasing (so
/// edges 2 and 3 run against Gmsh's, which go round the element); then the
/// interior nodes row by row, i fastest. Throws homesh::Error if p < 1.
Eigen::Matrix2Xi vtk_quad_node_indices(int p);

/// (p+1)^2 Gmsh node numbers of a quadrilateral of order p >= 1 in VTK order:
/// VTK node k is Gmsh node map[k] (element/quad_reference_nodes.h).
std::vector<int> gmsh_to_vtk_quad(int p);

/// 3 by (p+1)(p+2)(p+3)/6 integer coordinates (i, j, l) = p (r, s, t) of VTK's
/// Lagrange tetrahedron nodes of order p >= 1 (VTK_LAGRANGE_TETRAHEDRON = 71,
/// VTK 9.1's vtkHigherOrderTetra::BarycentricIndex), VTK order (above).
/// Throws homesh::Error if p < 1.
Eigen::Matrix3Xi vtk_tetrahedron_node_indices(int p);

/// (p+1)(p+2)(p+3)/6 Gmsh node numbers of a tetrahedron of order p >= 1 in VTK
/// order: VTK node k is Gmsh node map[k] (the node at the same reference
/// position, element/tet_reference_nodes.h). Throws homesh::Error if p < 1.
std::vector<int> gmsh_to_vtk_tetrahedron(int p);

/// p+1 Gmsh node numbers of a line of order p >= 1 in order along it, from
/// its first end to its second (the points of a VTK_POLY_LINE).
std::vector<int> line_nodes_along(int p);

}  // namespace homesh
