#pragma once
// The Morton (Z-order) of points on a Cartesian grid: sorted by the
// interleaved bits of their cells' indices (i, j), so that points close in
// the order are close in the plane. The fast-marching engine grows its
// crystals in this order of their seeds (voronoi/engines/fast_marching_engine.cpp).
#include <Eigen/Core>
#include <vector>

#include "voronoi/grid/cartesian_grid.h"

namespace homesh {

/// points: 2 by #P. Returns the indices 0..#P-1 in Morton order of the grid
/// cells holding the points (cells clamped at 0 below; ties by index).
std::vector<int> morton_order(const CartesianGrid& g, const Eigen::Matrix2Xd& points);

}  // namespace homesh
