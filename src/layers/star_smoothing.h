#pragma once
// Repair of the triangles the opening of the room squeezed (thesis Section 4.3):
// the elastic push keeps every triangle valid but can flatten those just ahead
// of a fast-moving stretch of the front (ahead of a trailing-edge fan, say) to
// a radius ratio far below anything in the input. Each such node is moved
// towards the centroid of its neighbours (Laplacian smoothing) only where that
// raises the worst radius ratio (Eq 4.17) of the triangles around it, so the
// mesh's worst Q never drops and no triangle turns clockwise.
#include <vector>

#include "core/mesh.h"

namespace homesh {

/// The worst radius ratio (Eq 4.17) of the triangles around each node of the
/// linear mesh m, -1 for a node whose triangles include a clockwise one, +1 for a
/// node no triangle uses. #nodes.
std::vector<double> star_quality(const Mesh& m);

/// Moves, in place, node i of the linear, counter-clockwise mesh m with
/// movable[i] (#nodes flags) and star_quality(m)[i] < floor[i] (#nodes) to
/// x + t (c - x), c the centroid of its neighbours, for the first t of 1, 1/2,
/// 1/4 that raises its star's worst radius ratio; sweeps until no node moves
/// (at most max_sweeps sweeps). Returns the number of moves.
int smooth_stars(Mesh& m, const std::vector<bool>& movable, const std::vector<double>& floor,
                 int max_sweeps = 10);

}  // namespace homesh
