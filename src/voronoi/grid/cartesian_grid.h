#pragma once
// The Cartesian grid on which the crystals of thesis Chapter 2 grow (Section
// 2.3): nodes x_i = x0 + i dx, y_j = y0 + j dy, i = 0..nx-1, j = 0..ny-1, and
// node (i, j) stored at the flat index i + nx j in every per-node array.
#include <Eigen/Core>

namespace homesh {

struct CartesianGrid {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< node (0, 0)
  double dx = 1.0;
  double dy = 1.0;
  int nx = 2;  ///< nodes along x, >= 2
  int ny = 2;  ///< nodes along y, >= 2

  /// The grid of nx by ny nodes spanning the box [lo, hi] (corners are nodes).
  /// Throws homesh::Error if nx < 2, ny < 2 or the box is empty.
  static CartesianGrid spanning(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, int nx,
                                int ny);

  /// The square-celled grid of spacing ds from lo over the box [lo, hi] (its
  /// last nodes at or beyond hi): the windows' grids (dual/window_regrowth.h).
  static CartesianGrid stepped(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double ds);

  /// The square-celled grid over the box [lo, hi] plus `margin` cells on each
  /// side, with `n` nodes along the box's longer side.
  static CartesianGrid covering(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, int n,
                                int margin);

  int node_count() const { return nx * ny; }
  int index(int i, int j) const { return i + nx * j; }
  /// The geometric step of Eqs 2.4-2.5, ds = min(dx, dy).
  double ds() const { return dx < dy ? dx : dy; }
  Eigen::Vector2d point(int i, int j) const { return origin + Eigen::Vector2d(i * dx, j * dy); }
  /// The node nearest to p, clamped to the grid.
  Eigen::Vector2i nearest_node(const Eigen::Vector2d& p) const;
};

/// A scalar given at the nodes of `grid` (values: grid.node_count()), sampled
/// at the nodes: values(grid.index(i, j)) = f(grid.point(i, j)).
template <class F>
Eigen::VectorXd sample_on_grid(const CartesianGrid& grid, F&& f) {
  Eigen::VectorXd values(grid.node_count());
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) values(grid.index(i, j)) = f(grid.point(i, j));
  return values;
}

/// The bilinear interpolant of `values` (grid.node_count(), one per node) at
/// p, clamped to the grid's box.
double bilinear_at(const CartesianGrid& grid, const Eigen::VectorXd& values,
                   const Eigen::Vector2d& p);

}  // namespace homesh
