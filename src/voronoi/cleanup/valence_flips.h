#pragma once
// Edge flips that make the interior nodes' valences more regular: a node of a
// lattice of equilateral triangles has six, and a mesh whose nodes have five
// and seven in pairs keeps triangles that no smoothing makes equilateral (the
// connectivity fixes the angles' mean at each node to 360 / valence). A flip
// of edge (a, b) in quad (a, c, b, d) takes one from a and b and gives one to
// c and d; it is made when it lowers the sum of (valence - 6)^2 over those of
// the four that are interior nodes and its two new triangles are no worse
// than `floor` in `quality` (the smoothing after it shapes them). The valence
// relaxation of Frey and Field ("Mesh relaxation: a new technique for
// improving triangulations", IJNME 31, 1991).
#include <vector>

#include "core/mesh.h"
#include "layers/edge_flips.h"

namespace homesh {

/// m: linear, counter-clockwise triangles; interior: one flag per node, 1 for
/// a node whose valence counts (a surface node); lines (boundary and embedded
/// curves) are never flipped, nor edges between triangles of two surfaces.
/// Sweeps until no edge flips, at most `max_sweeps`. Returns the flips.
int flip_to_regular_valence(Mesh& m, const std::vector<char>& interior,
                            const TriangleQuality& quality, double floor, int max_sweeps = 10);

}  // namespace homesh
