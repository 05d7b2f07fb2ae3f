#pragma once
// Interior nodes with three triangles round them: the dual of a Voronoi
// region with three neighbours, which Lloyd's iteration and smoothing cannot
// make good (the node sits inside the triangle of its neighbours, its
// triangles' angles near 120/30/30 degrees, and smoothing keeps the
// connectivity). Such a node goes and its three triangles become the one of
// its neighbours: that triangle holds the node, so it is counter-clockwise
// when theirs are.
#include <array>
#include <vector>

namespace homesh {

/// Removes, in place, every node k with interior[k] != 0 that is a corner of
/// exactly three triangles of one surface (triangle_surface) forming a closed
/// fan, their union replacing them; again while the removals make new ones.
/// The nodes stay numbered (a removed one is in no triangle). Returns how
/// many went.
int remove_valence_three(std::vector<std::array<int, 3>>& triangles,
                         std::vector<int>& triangle_surface, const std::vector<char>& interior);

}  // namespace homesh
