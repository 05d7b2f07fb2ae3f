#pragma once
// Raising a volume mesh to a higher (or lower) order with straight sides
// (issue 24; core/raise_order.h for planar meshes).
#include "core/volume_mesh.h"

namespace homesh {

/// The volume mesh `m` (of any order q) at order p, 1 <= p <= kMaxTetrahedronOrder,
/// with straight-sided elements; throws homesh::Error naming p if out of range.
///
/// Only the corner nodes of m (and the nodes of its point elements) are kept, in
/// their original order; new nodes follow. Every new node is a point of the
/// order-p lattice of some element: it sits on the sub-simplex (edge, face or
/// interior) of the corners whose barycentric index is nonzero, at the affine
/// combination of those corners by that index / p. Elements that share the
/// sub-simplex share the node: its key is the set of (corner node, index) pairs,
/// which does not depend on how an element orients the edge or face.
///
/// Nodes are created lines first, then triangles, then tetrahedra, element by
/// element in Gmsh's node order, so a node on a line is on that line's curve
/// (dim 1, u interpolated between the line's ends when both have one), a node
/// on a triangle's edge or face (and on no line) is on its surface (dim 2, u and
/// v interpolated from the triangle's corners when all three have them), and
/// any other node is inside its tetrahedron's volume (dim 3).
/// Point elements (remapped), entities and physical groups are copied.
VolumeMesh raise_volume_order(const VolumeMesh& m, int p);

}  // namespace homesh
