#pragma once
// Certified validity of every tetrahedron of a volume mesh (issue 24): as
// quality/mesh_validity.h for planar meshes, an element counts as valid only
// if the Bezier bounds of its det J (quality/tet_bezier_jacobian.h) prove
// det J > 0 on the whole element; undecided elements count as invalid.
#include <vector>

#include "core/volume_mesh.h"
#include "quality/jacobian_bounds.h"
#include "quality/mesh_validity.h"

namespace homesh {

/// Bounds of det J of every tetrahedron of m, on `threads` threads (0: one per
/// core). MeshValidity's per-element vectors run over the tetrahedra. Throws
/// homesh::Error if m's order exceeds kMaxTetrahedronOrder.
MeshValidity volume_validity(const VolumeMesh& m, const BoundsOptions& opt = {}, int threads = 0);

/// volume_validity(m, opt, threads), taking tetrahedron e's bounds from entry
/// known_index[e] of `known` where that is >= 0 (and known was refined by the
/// same options: else every tetrahedron is bounded). For the elements a change
/// left as they were (a split's untouched tetrahedra, renumbered).
MeshValidity volume_validity(const VolumeMesh& m, const MeshValidity& known,
                             const std::vector<int>& known_index, const BoundsOptions& opt = {},
                             int threads = 0);

/// volume_validity(m, opt, threads) given `known`, the validity of `previous`:
/// each tetrahedron whose nodes are at the same coordinates in both (bit for
/// bit: the bounds are a function of them) keeps known's bounds; the others are
/// bounded anew. Every one is if the order or the number of tetrahedra differ,
/// or known was refined by other options. The 3D twin of mesh_validity's.
MeshValidity volume_validity(const VolumeMesh& m, const VolumeMesh& previous,
                             const MeshValidity& known, const BoundsOptions& opt = {},
                             int threads = 0);

}  // namespace homesh
