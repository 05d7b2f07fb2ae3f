#pragma once
// Splitting tetrahedra at the centroid of their corners (issue 24): the local
// topological repair for a tetrahedron whose four corners all lie on the wall.
// Its only free high-order nodes are those of its interior edges, so when its
// curved faces crowd it no interior node can mend it; split into four, each
// child has a corner inside the volume and the optimiser a node to move.
#include <vector>

#include "core/volume_mesh.h"

namespace homesh {

/// Splits each tetrahedron of m listed in `which` (indices, any order, no
/// repeats) into the four with the centroid M of its corners in place of one
/// corner: child f is the parent with corner f replaced by M, so it keeps the
/// parent's orientation and its face opposite M is the parent's face f. The
/// split is conforming: the parent's faces, edges and their nodes stay as they
/// are, so its neighbours are untouched.
///
/// At order p each child's nodes are the parent's map at the child's lattice
/// points: the children reproduce the parent's shape exactly (the restriction
/// of a polynomial map of degree p to a sub-simplex is one of degree p in the
/// child's coordinates). A child node that is a parent lattice point is the
/// parent's node (its faces' and, p >= 4, its interior nodes); the others are
/// new nodes inside the parent's volume (dim 3, the parent's entity), shared
/// by the children. Child 0 takes the parent's place, children 1-3 are
/// appended, and the tetrahedra are then grouped by entity (group_by_entity).
/// Returns, for each tetrahedron after the split, the index before the split
/// of the one it is or came from.
std::vector<int> split_at_centroid(VolumeMesh& m, const std::vector<int>& which);

/// The tetrahedra of m whose four corners are all on the boundary (classified on
/// a model point, curve or surface) and whose flag in `bad` is set.
std::vector<int> wall_capped(const VolumeMesh& m, const std::vector<char>& bad);

}  // namespace homesh
