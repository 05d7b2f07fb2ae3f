#pragma once
// Certified validity of every tetrahedron of a volume mesh (issue 24): as
// quality/mesh_validity.h for planar meshes, an element counts as valid only
// if the Bezier bounds of its det J (quality/tet_bezier_jacobian.h) prove
// det J > 0 on the whole element; undecided elements count as invalid.
#include "core/volume_mesh.h"
#include "quality/jacobian_bounds.h"
#include "quality/mesh_validity.h"

namespace homesh {

/// Bounds of det J of every tetrahedron of m, on `threads` threads (0: one per
/// core). MeshValidity's per-element vectors run over the tetrahedra. Throws
/// homesh::Error if m's order exceeds kMaxTetrahedronOrder.
MeshValidity volume_validity(const VolumeMesh& m, const BoundsOptions& opt = {}, int threads = 0);

/// volume_validity(m) with default bounds, reusing `known` (the default-bounds
/// validity of `previous`) for each tetrahedron whose nodes are the same nodes
/// at the same coordinates in both (bit for bit); the others are bounded anew.
/// Everything is bounded anew if the order or the number of tetrahedra differ.
MeshValidity volume_validity(const VolumeMesh& m, const VolumeMesh& previous,
                             const MeshValidity& known);

}  // namespace homesh
