#pragma once
// An algebraic first guess for the interior of a mesh whose wall is curved: every
// node near a wall follows the deviation of the nearest wall line from its chord,
// at the node's projection on that chord, fading to nothing one `radius` of that
// line's length away. A stack of thin boundary-layer elements over a wall edge
// then moves as a whole with it, each element keeping its thickness, where the
// wall's bulge is larger than the first elements (the idea of Gmsh's
// HighOrderFastCurving, Toulorge, Lambrechts & Remacle, JCP 2016, without its
// need to recognise the layers' columns). The result is only a guess: the curve
// pipeline certifies it and solves where it is poor.
#include <Eigen/Core>
#include <vector>

#include "core/mesh.h"

namespace homesh {

/// The displacement (2 by #nodes) of every node i with free[i] of the mesh `m`
/// (order p, its wall lines straight) when its boundary nodes move to `target`:
/// for a node at distance s from the chord of its nearest line (a moved one),
/// projected on it at t in [0, 1], the line's deviation at t (interpolated from
/// its nodes) times 1 - 3 r^2 + 2 r^3, r = s / (radius * chord length), 0 for r >= 1.
/// Nodes without free[i] get 0.
Eigen::Matrix2Xd propagate_wall_displacement(const Mesh& m, const Eigen::Matrix2Xd& target,
                                             const std::vector<bool>& free, double radius);

}  // namespace homesh
