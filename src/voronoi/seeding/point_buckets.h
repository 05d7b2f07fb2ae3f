#pragma once
// Points in buckets for the neighbour searches of seeding: a hierarchy of
// uniform grids, cells `cell` * 2^k for k = 0, 1, ... up to the box, every
// point in each. A search within r scans the level whose cells are about r
// wide, so its cost does not grow with the ratio of the largest to the
// smallest size of the metric (a single grid of the smallest cells scanned
// (r / cell)^2 mostly empty buckets per search: 14 % of the voronoi stage on
// NACA-7526, whose far field is 50 times its walls' size).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

namespace homesh {

class PointBuckets {
 public:
  /// Buckets over the box [lo, hi], the finest `cell` wide (> 0), but at
  /// most kMaxCells a side (a 100:1 metric's smallest size would otherwise ask
  /// for 1e10 buckets; searches return the same points, from more buckets).
  PointBuckets(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double cell) : lo_(lo) {
    const double extent = std::max((hi - lo).maxCoeff(), cell);
    for (double c = std::max(cell, extent / kMaxCells);; c *= 2) {
      Level l;
      l.cell = c;
      l.nx = std::max(1, static_cast<int>(std::ceil((hi.x() - lo.x()) / c)));
      l.ny = std::max(1, static_cast<int>(std::ceil((hi.y() - lo.y()) / c)));
      l.head.assign(static_cast<std::size_t>(l.nx) * l.ny, -1);
      levels_.push_back(std::move(l));
      if (c >= extent) break;
    }
  }

  void add(const Eigen::Vector2d& p) {
    const int k = static_cast<int>(points_.size());
    points_.push_back(p);
    for (Level& l : levels_) {
      const int b = l.bucket(p, lo_);
      l.next.push_back(l.head[b]);
      l.head[b] = k;
    }
  }

  /// Calls f(point) for every point within Euclidean distance r of p (and
  /// some farther ones) while f returns true; false if some call did not.
  template <class F>
  bool all_of_near(const Eigen::Vector2d& p, double r, F&& f) const {
    return all_of_near_index(p, r, [&](int k) { return f(points_[k]); });
  }

  /// The same with f(k), k the point's place in the order of add.
  template <class F>
  bool all_of_near_index(const Eigen::Vector2d& p, double r, F&& f) const {
    // The finest level whose cells are at least r / 2 wide: at most 5 x 5 cells.
    std::size_t k = 0;
    while (k + 1 < levels_.size() && levels_[k].cell < 0.5 * r) ++k;
    const Level& l = levels_[k];
    const int i0 = l.clamp_x(std::floor((p.x() - r - lo_.x()) / l.cell));
    const int i1 = l.clamp_x(std::floor((p.x() + r - lo_.x()) / l.cell));
    const int j0 = l.clamp_y(std::floor((p.y() - r - lo_.y()) / l.cell));
    const int j1 = l.clamp_y(std::floor((p.y() + r - lo_.y()) / l.cell));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        for (int q = l.head[i + l.nx * j]; q >= 0; q = l.next[q])
          if (!f(q)) return false;
    return true;
  }

  const std::vector<Eigen::Vector2d>& points() const { return points_; }
  int levels() const { return static_cast<int>(levels_.size()); }

 private:
  static constexpr double kMaxCells = 1024;
  struct Level {
    double cell = 1;
    int nx = 1, ny = 1;
    std::vector<int> head, next;
    int clamp_x(double v) const {
      return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(nx - 1)));
    }
    int clamp_y(double v) const {
      return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(ny - 1)));
    }
    int bucket(const Eigen::Vector2d& p, const Eigen::Vector2d& lo) const {
      return clamp_x(std::floor((p.x() - lo.x()) / cell)) +
             nx * clamp_y(std::floor((p.y() - lo.y()) / cell));
    }
  };
  Eigen::Vector2d lo_;
  std::vector<Level> levels_;
  std::vector<Eigen::Vector2d> points_;
};

}  // namespace homesh
