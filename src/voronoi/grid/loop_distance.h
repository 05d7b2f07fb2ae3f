#pragma once
// The domain of a Voronoi problem from its boundary: closed polygons (the CAD
// boundary loops sampled finely) turned into a signed distance on the grid.
#include <Eigen/Core>
#include <vector>

#include "voronoi/grid/cartesian_grid.h"

namespace homesh {

/// loops: closed polygons, each 2 by n (n >= 3, the last point joined to the
/// first). Returns grid.node_count() values: the Euclidean distance to the
/// nearest polygon edge where that is below `band`, else `band`, negative
/// inside the domain (even-odd rule over all loops: a hole is a loop inside
/// another). Nodes on an edge count as inside (distance 0). The polygons are
/// first decimated to chords that pass within 0.01 grid cells of every
/// sample they skip: the distances are within that of the samples' polygon.
Eigen::VectorXd loop_signed_distance(const CartesianGrid& grid,
                                     const std::vector<Eigen::Matrix2Xd>& loops, double band);

/// Even-odd point-in-polygon over all loops (the same rule).
bool inside_loops(const std::vector<Eigen::Matrix2Xd>& loops, const Eigen::Vector2d& p);

}  // namespace homesh
