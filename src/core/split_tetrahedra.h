#pragma once
// Splitting tetrahedra at the centroid of their corners or at the midpoint of
// an edge (issue 24): the local topological repairs for a tetrahedron whose
// four corners all lie on the wall. Its only free high-order nodes are those of
// its interior edges, so when its curved faces crowd it no interior node can
// mend it; split, each child has a corner inside the volume and the optimiser
// a node to move.
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

/// Splits the edge between corner nodes a and b at its midpoint M (the edge's
/// curved midpoint): every tetrahedron with that edge becomes the two with M in
/// place of b and of a, so each keeps its orientation. Nodes as in
/// split_at_centroid: the children reproduce their parents exactly; a new node
/// on a face the parents share is made once, so the split is conforming. M and
/// the other new nodes are inside the volume (dim 3): the edge must not lie on
/// the mesh's boundary. The way to give a tetrahedron squeezed between two
/// curved wall faces and an interior edge lying on the wall a vertex the
/// optimiser can lift into the volume, together with the tetrahedra round the
/// edge. Returns, for each tetrahedron after the split, the index before the
/// split of the one it is or came from.
std::vector<int> split_edge(VolumeMesh& m, int a, int b);

/// The tetrahedra of m whose four corners are all on the boundary (classified on
/// a model point, curve or surface) and whose flag in `bad` is set.
std::vector<int> wall_capped(const VolumeMesh& m, const std::vector<char>& bad);

}  // namespace homesh
