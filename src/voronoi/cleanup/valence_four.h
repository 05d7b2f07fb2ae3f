#pragma once
// Interior nodes with four triangles round them where the quad of their
// neighbours, split by one diagonal, is better without them: a seed too many
// at a convex corner of the boundary or where two fronts meet, which
// smoothing cannot fix (it keeps the connectivity) and an edge flip cannot
// either (every flip keeps the node). The node goes and two triangles of its
// four neighbours replace its four, where that raises the worst quality of
// the spot; unlike a valence-3 node (valence_three.h), which always goes, a
// valence-4 node is often right (a quad of a regular lattice), so the choice
// is by quality, on the smoothed positions.
#include <Eigen/Core>
#include <vector>

#include "core/mesh.h"
#include "layers/edge_flips.h"

namespace homesh {

/// m: linear, counter-clockwise triangles; free_node: one flag per node, 1
/// for a node that may go. Each node with free_node set that is a corner of
/// exactly four triangles of one surface forming a closed fan (ring a0 a1 a2
/// a3) goes if the better split of the quad, (a0 a1 a2, a0 a2 a3) or (a1 a2
/// a3, a1 a3 a0), is counter-clockwise and its worse triangle beats the worst
/// of the four by more than `gain` in `quality`; again while removals make
/// new candidates. The nodes stay numbered (a removed one is in no triangle
/// after); m.tri loses two columns per removal. Returns the removed nodes,
/// ascending.
std::vector<int> remove_valence_four(Mesh& m, const std::vector<char>& free_node,
                                     const TriangleQuality& quality, double gain = 1e-3);

}  // namespace homesh
