#pragma once
// Raising a mesh to a higher (or lower) polynomial order with straight sides.
#include "core/mesh.h"

namespace homesh {

/// The mesh `m` (of any order q) at order p, 1 <= p <= kMaxOrder (core/mesh.h),
/// with straight-sided elements; throws homesh::Error naming p if out of range.
///
/// Only the corner nodes of m are used: nodes that m uses solely as edge or
/// interior nodes of order q > 1 are dropped, every other node is kept, in its
/// original order (so for q = 1 node i of m is node i of the result). New nodes
/// follow, placed by the affine map of their element's corners at
/// reference_nodes(p) / reference_line_nodes(p):
///  - the p-1 nodes of each edge, one set per unordered corner pair shared by the
///    triangles, quadrilaterals and boundary lines on it, created from the lower
///    to the higher corner index and listed by each element in its own edge
///    direction; edges numbered by first appearance, triangles first, then
///    quadrilaterals, then lines;
///  - then the (p-1)(p-2)/2 interior nodes of each triangle, triangle by triangle;
///  - then the (p-1)^2 interior nodes of each quadrilateral (Gmsh order,
///    element/quad_reference_nodes.h), placed by the bilinear map of its corners.
/// Node count: V + (p-1) E + (p-1)(p-2)/2 T + (p-1)^2 Q.
///
/// Classification of new nodes: an edge carrying a boundary line is on that
/// line's curve (dim 1, tag line_entity, u interpolated linearly between the
/// line's end nodes when both have a u, NaN otherwise); any other edge node and
/// every interior node is on its element's surface (dim 2, tag tri_entity or
/// quad_entity).
/// Point elements (remapped), entities and physical groups are copied.
Mesh raise_order(const Mesh& m, int p);

}  // namespace homesh
