#include "voronoi/cartesian_grid.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace homesh {

CartesianGrid CartesianGrid::spanning(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, int nx,
                                      int ny) {
  if (nx < 2 || ny < 2) throw Error("CartesianGrid: need at least 2 by 2 nodes");
  if (!(hi.x() > lo.x() && hi.y() > lo.y())) throw Error("CartesianGrid: empty box");
  CartesianGrid g;
  g.origin = lo;
  g.nx = nx;
  g.ny = ny;
  g.dx = (hi.x() - lo.x()) / (nx - 1);
  g.dy = (hi.y() - lo.y()) / (ny - 1);
  return g;
}

Eigen::Vector2i CartesianGrid::nearest_node(const Eigen::Vector2d& p) const {
  const int i = static_cast<int>(std::lround((p.x() - origin.x()) / dx));
  const int j = static_cast<int>(std::lround((p.y() - origin.y()) / dy));
  return {std::clamp(i, 0, nx - 1), std::clamp(j, 0, ny - 1)};
}

}  // namespace homesh
