#pragma once
// The interior nodes of a triangle of order p from its (possibly curved) edges:
// the degree-p polynomial map that interpolates the corners and edge nodes and
// has no interior (bubble) mode in the hierarchical basis of Szabo & Babuska
// ("Finite Element Analysis", 1991, Sec. 6.1: the edge modes l_a l_b phi(l_b - l_a)),
// the blending Sherwin & Peiro use to curve a triangle from its edges
// (IJNME 53, 2002). Each edge's deviation from its chord, d(t) = t (1 - t) q(t),
// is carried into the triangle as
//   D(l) = l_a l_b q((1 + l_b - l_a) / 2),
// which is d on the edge and vanishes on the two others; the interior nodes sit
// at the affine map of the corners plus the three D's.
//
// A quadrilateral of order p likewise gets the transfinite (Coons) interpolation of
// its edges with linear blending (Gordon & Hall, "Construction of curvilinear
// co-ordinate systems and applications to mesh generation", IJNME 7, 1973), written
// as the bilinear map of its corners plus each edge's deviation from its chord
// carried linearly to the opposite edge: on [0, 1]^2,
//   x(u, v) = bilinear + (1 - v) d_0(u) + u d_1(v) + v d_2(1 - u) + (1 - u) d_3(1 - v),
// d_k the deviation of edge k (Gmsh: 0-1, 1-2, 2-3, 3-0), which vanishes at the corners.
//
// Used where curving moves only the boundary of an element (the placed first
// guess, the elements left outside a local solve): the straight interior it
// replaces crowds the whole curvature into the first row of nodes, a map whose
// derivatives are O(1/h) larger than the wall's, which costs both the Jacobian
// ratio and the accuracy of a solver on the mesh.
#include <Eigen/Core>
#include <vector>

#include "core/mesh.h"

namespace homesh {

/// X: 2 by (p+1)(p+2)/2 node coordinates of a triangle of order p, Gmsh order.
/// Returns X with its interior nodes (index >= 3p) replaced by the blending of
/// its edges; p < 3 (no interior nodes) returns X.
Eigen::Matrix2Xd blend_interior(const Eigen::Matrix2Xd& X, int p);

/// X: 2 by (p+1)^2 node coordinates of a quadrilateral of order p, Gmsh order.
/// Returns X with its interior nodes (index >= 4p) replaced by the Coons
/// interpolation of its edges; p < 2 returns X.
Eigen::Matrix2Xd blend_quad_interior(const Eigen::Matrix2Xd& X, int p);

/// blend_interior on every triangle, blend_quad_interior on every quadrilateral
/// of m with an edge node i where moved[i].
void blend_interiors(Mesh& m, const std::vector<bool>& moved);

}  // namespace homesh
