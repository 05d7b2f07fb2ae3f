#include "voronoi/grid/cartesian_grid.h"

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

CartesianGrid CartesianGrid::stepped(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                                     double ds) {
  CartesianGrid g;
  g.origin = lo;
  g.dx = g.dy = ds;
  g.nx = static_cast<int>(std::ceil((hi.x() - lo.x()) / ds)) + 1;
  g.ny = static_cast<int>(std::ceil((hi.y() - lo.y()) / ds)) + 1;
  return g;
}

CartesianGrid CartesianGrid::covering(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, int n,
                                      int margin) {
  const double ds = (hi - lo).maxCoeff() / (n - 1 - 2 * margin);
  CartesianGrid g;
  g.origin = lo - Eigen::Vector2d::Constant(margin * ds);
  g.dx = g.dy = ds;
  g.nx = static_cast<int>(std::ceil((hi.x() - lo.x()) / ds)) + 1 + 2 * margin;
  g.ny = static_cast<int>(std::ceil((hi.y() - lo.y()) / ds)) + 1 + 2 * margin;
  return g;
}

Eigen::Vector2i CartesianGrid::nearest_node(const Eigen::Vector2d& p) const {
  const int i = static_cast<int>(std::lround((p.x() - origin.x()) / dx));
  const int j = static_cast<int>(std::lround((p.y() - origin.y()) / dy));
  return {std::clamp(i, 0, nx - 1), std::clamp(j, 0, ny - 1)};
}

double bilinear_at(const CartesianGrid& g, const Eigen::VectorXd& values,
                   const Eigen::Vector2d& p) {
  const double u = std::clamp((p.x() - g.origin.x()) / g.dx, 0.0, g.nx - 1.0);
  const double v = std::clamp((p.y() - g.origin.y()) / g.dy, 0.0, g.ny - 1.0);
  const int i = std::min(static_cast<int>(u), g.nx - 2);
  const int j = std::min(static_cast<int>(v), g.ny - 2);
  const double a = u - i, b = v - j;
  return (1 - a) * (1 - b) * values(g.index(i, j)) + a * (1 - b) * values(g.index(i + 1, j)) +
         a * b * values(g.index(i + 1, j + 1)) + (1 - a) * b * values(g.index(i, j + 1));
}

}  // namespace homesh
