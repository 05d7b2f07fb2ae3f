#pragma once
// What the seedings share (metric_seeding.h, column_seeds.h): the domain's
// inside test of a metric ball, and seeds in buckets with their metrics for
// the spacing test.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "voronoi/grid/cartesian_grid.h"
#include "voronoi/metric/metric_field.h"
#include "voronoi/seeding/lloyd_relaxation.h"
#include "voronoi/seeding/point_buckets.h"

namespace homesh {

// The domain's signed distance at a point (the grid box's when `domain` is
// empty), and whether a metric ball lies inside.
struct DomainTest {
  const CartesianGrid& g;
  const Eigen::VectorXd& domain;

  double at(const Eigen::Vector2d& p) const {
    if (domain.size() == 0) {
      const Eigen::Vector2d hi = g.point(g.nx - 1, g.ny - 1);
      return -std::min(
          {p.x() - g.origin.x(), p.y() - g.origin.y(), hi.x() - p.x(), hi.y() - p.y()});
    }
    return bilinear_at(g, domain, p);
  }
  // The metric ball of radius r round q (root_inv = M^-1/2) inside the
  // domain, tested at 16 points of its boundary: the metric distance to the
  // boundary is >= r.
  bool ball_inside(const Eigen::Vector2d& q, const Eigen::Matrix2d& root_inv, double r) const {
    static const std::array<Eigen::Vector2d, 16> direction = [] {
      std::array<Eigen::Vector2d, 16> out;
      for (int k = 0; k < 16; ++k) {
        const double a = M_PI * k / 8;
        out[k] = {std::cos(a), std::sin(a)};
      }
      return out;
    }();
    if (at(q) >= 0.0) return false;
    for (const Eigen::Vector2d& d : direction)
      if (at(q + r * (root_inv * d)) >= 0.0) return false;
    return true;
  }
};

// Seeds in buckets with the metric at each, taken once: the spacing test
// meets each seed many times.
class SpacedSeeds {
 public:
  SpacedSeeds(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double cell,
              const MetricField& metric)
      : buckets_(lo, hi, cell), metric_(metric), midpoint_(metric.anisotropy() > kIsotropic) {}
  void add(const Eigen::Vector2d& p) { add(p, metric_.metric_at(p)); }
  /// group >= 0: a set of seeds not spaced from each other (a fan's columns).
  void add(const Eigen::Vector2d& p, const Eigen::Matrix2d& Mp, int group = -1) {
    buckets_.add(p);
    M_.push_back(Mp);
    group_.push_back(group);
    if (midpoint_) longest_.push_back(metric_max_speed(Mp));
  }
  // Whether q is at least `spacing` (metric length, Mq at q) from every seed
  // within `reach`: in the mean of the two points' metrics, or, where the
  // metric is anisotropic, in the metric at their midpoint. Along a curved
  // wall at 100:1 the mean misjudges: each end's fine axis is turned from
  // the chord's normal, so the chord's length along the wall counts as if it
  // ran across it (two seeds half a size apart on a row measured 0.9 to 1.05
  // instead of about 0.5 on NACA-7526's nose); the wall's tangent at the
  // midpoint is the chord's.
  bool spaced(const Eigen::Vector2d& q, const Eigen::Matrix2d& Mq, double spacing, double reach,
              int group = -1) const {
    const double s2 = spacing * spacing;
    if (!midpoint_)
      return buckets_.all_of_near_index(q, reach, [&](int k) {
        const Eigen::Vector2d v = q - buckets_.points()[k];
        return v.dot(0.5 * (Mq + M_[k]) * v) >= s2;
      });
    const double hq = metric_max_speed(Mq);
    return buckets_.all_of_near_index(q, reach, [&](int k) {
      if (group >= 0 && group_[k] == group) return true;
      const Eigen::Vector2d p = buckets_.points()[k], v = q - p;
      // Farther than twice the larger of the two long semi-axes: spaced.
      const double h = std::max(hq, longest_[k]);
      if (v.squaredNorm() >= 4 * s2 * h * h) return true;
      return v.dot(metric_.metric_at(0.5 * (p + q)) * v) >= s2;
    });
  }

  // The seed other than q nearest to it within `reach` (Euclidean), in the
  // metric Mq; q itself if there is none.
  Eigen::Vector2d nearest(const Eigen::Vector2d& q, const Eigen::Matrix2d& Mq, double reach) const {
    Eigen::Vector2d best = q;
    double d_best = std::numeric_limits<double>::infinity();
    buckets_.all_of_near(q, reach, [&](const Eigen::Vector2d& p) {
      const Eigen::Vector2d v = p - q;
      const double d = v.dot(Mq * v);
      if (d > 0 && d < d_best) {
        d_best = d;
        best = p;
      }
      return true;
    });
    return best;
  }

 private:
  PointBuckets buckets_;
  const MetricField& metric_;
  bool midpoint_;
  std::vector<Eigen::Matrix2d> M_;
  std::vector<int> group_;
  std::vector<double> longest_;  // each seed's longest semi-axis (with midpoint_)
};

}  // namespace homesh
