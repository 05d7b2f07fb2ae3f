#pragma once
// Edge flips that raise the worst radius ratio (Eq 4.17) of a linear mesh: the
// diagonal swap of thesis Fig 4.5c applied to the existing mesh while the room
// for the layers opens, so triangles squeezed against the moving front re-join
// better-placed neighbours instead of degenerating.
#include <functional>
#include <vector>

#include "core/mesh.h"

namespace homesh {

/// Flips, in place, each edge shared by two counter-clockwise triangles of the
/// same surface, and not a line element (an embedded curve), when the other
/// diagonal of their quad gives two
/// counter-clockwise triangles whose worst radius ratio is larger by more than
/// `gain`; sweeps until no edge flips (at most `max_sweeps` sweeps). Nodes, the
/// triangle count and each triangle's surface are kept. Returns the number of
/// flips. m must be linear.
int flip_edges(Mesh& m, double gain = 1e-3, int max_sweeps = 10);

/// As above, flipping only edges shared by two of `triangles` (distinct
/// indices): after a local change, at the cost of the triangles it touched.
int flip_edges(Mesh& m, const std::vector<int>& triangles, double gain = 1e-3, int max_sweeps = 10);

/// The quality of a counter-clockwise straight triangle (corners 2 by 3), higher better.
using TriangleQuality = std::function<double(const Eigen::Matrix<double, 2, 3>&)>;

/// The same on every triangle with `quality` in place of the radius ratio
/// (e.g. the mean ratio in a metric).
int flip_edges(Mesh& m, const TriangleQuality& quality, double gain = 1e-3, int max_sweeps = 10);

}  // namespace homesh
