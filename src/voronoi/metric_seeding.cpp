#include "voronoi/metric_seeding.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace homesh {
namespace {

// Seeds in buckets of a uniform grid, for the neighbour search.
class Buckets {
 public:
  Buckets(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double cell)
      : lo_(lo), cell_(cell) {
    nx_ = std::max(1, static_cast<int>(std::ceil((hi.x() - lo.x()) / cell)));
    ny_ = std::max(1, static_cast<int>(std::ceil((hi.y() - lo.y()) / cell)));
    head_.assign(static_cast<std::size_t>(nx_) * ny_, -1);
  }
  void add(const Eigen::Vector2d& p) {
    points_.push_back(p);
    const int b = bucket(p);
    next_.push_back(head_[b]);
    head_[b] = static_cast<int>(points_.size()) - 1;
  }
  // Calls f(point) for the points within Euclidean distance r of p (and some more).
  template <class F>
  bool all_of_near(const Eigen::Vector2d& p, double r, F&& f) const {
    const int i0 = clamp_x(std::floor((p.x() - r - lo_.x()) / cell_));
    const int i1 = clamp_x(std::floor((p.x() + r - lo_.x()) / cell_));
    const int j0 = clamp_y(std::floor((p.y() - r - lo_.y()) / cell_));
    const int j1 = clamp_y(std::floor((p.y() + r - lo_.y()) / cell_));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        for (int k = head_[i + nx_ * j]; k >= 0; k = next_[k])
          if (!f(points_[k])) return false;
    return true;
  }
  const std::vector<Eigen::Vector2d>& points() const { return points_; }

 private:
  int clamp_x(double v) const { return std::clamp(static_cast<int>(v), 0, nx_ - 1); }
  int clamp_y(double v) const { return std::clamp(static_cast<int>(v), 0, ny_ - 1); }
  int bucket(const Eigen::Vector2d& p) const {
    return clamp_x(std::floor((p.x() - lo_.x()) / cell_)) +
           nx_ * clamp_y(std::floor((p.y() - lo_.y()) / cell_));
  }
  Eigen::Vector2d lo_;
  double cell_;
  int nx_ = 1, ny_ = 1;
  std::vector<int> head_, next_;
  std::vector<Eigen::Vector2d> points_;
};

}  // namespace

Eigen::Matrix2Xd metric_interior_seeds(const CartesianGrid& g, const Eigen::VectorXd& domain,
                                       const MetricField& metric,
                                       const Eigen::Matrix2Xd& boundary_seeds,
                                       const SeedingOptions& o) {
  const Eigen::Vector2d lo = g.origin;
  const Eigen::Vector2d hi = g.origin + Eigen::Vector2d((g.nx - 1) * g.dx, (g.ny - 1) * g.dy);
  const auto domain_at = [&](const Eigen::Vector2d& p) {
    if (domain.size() == 0)
      return -std::min({p.x() - lo.x(), p.y() - lo.y(), hi.x() - p.x(), hi.y() - p.y()});
    return bilinear_at(g, domain, p);
  };
  // The metric ball of radius r round q inside the domain, tested at 16
  // points of its boundary: the metric distance to the boundary is >= r.
  const auto ball_inside = [&](const Eigen::Vector2d& q, const Eigen::Matrix2d& root_inv,
                               double r) {
    if (domain_at(q) >= 0.0) return false;
    for (int k = 0; k < 16; ++k) {
      const double a = M_PI * k / 8;
      if (domain_at(q + r * (root_inv * Eigen::Vector2d(std::cos(a), std::sin(a)))) >= 0.0)
        return false;
    }
    return true;
  };
  // Buckets as small as the smallest semi-axis of the field; neighbours are
  // searched within spacing (1 + annulus) times twice the local largest
  // semi-axis (a graded metric changes by less than 2 over that distance).
  double h_min = metric.min_speed();
  Buckets buckets(lo, hi, std::max(h_min * o.spacing, 1e-9 * (hi - lo).norm()));
  std::vector<Eigen::Vector2d> active;
  for (int k = 0; k < boundary_seeds.cols(); ++k) {
    buckets.add(boundary_seeds.col(k));
    active.push_back(boundary_seeds.col(k));
  }
  std::mt19937 gen(o.random_seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector2d> interior;
  const auto try_add = [&](const Eigen::Vector2d& q) {
    const Eigen::Matrix2d Mq = metric.metric_at(q);
    const Eigen::Matrix2d root_inv =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(Mq).operatorInverseSqrt();
    if (!ball_inside(q, root_inv, o.boundary_gap)) return false;
    const double reach = 2.0 * o.spacing * (1 + o.annulus) * metric_max_speed(Mq);
    const bool spaced = buckets.all_of_near(q, reach, [&](const Eigen::Vector2d& p) {
      const Eigen::Vector2d v = q - p;
      return v.dot(0.5 * (Mq + metric.metric_at(p)) * v) >= o.spacing * o.spacing;
    });
    if (!spaced) return false;
    buckets.add(q);
    active.push_back(q);
    interior.push_back(q);
    return true;
  };
  if (active.empty()) {
    // No boundary seeds: start from the deepest node.
    Eigen::Index deepest = 0;
    if (domain.size() > 0) domain.minCoeff(&deepest);
    const int d = static_cast<int>(deepest);
    try_add(domain.size() > 0 ? g.point(d % g.nx, d / g.nx) : 0.5 * (lo + hi));
  }
  while (!active.empty()) {
    const std::size_t pick = static_cast<std::size_t>(unit(gen) * active.size()) % active.size();
    const Eigen::Vector2d p = active[pick];
    // Directions in the unit ball of M(p): x = M^-1/2 (cos a, sin a).
    const Eigen::Matrix2d root_inv =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(metric.metric_at(p)).operatorInverseSqrt();
    bool placed = false;
    for (int t = 0; t < o.tries && !placed; ++t) {
      const double a = 2 * M_PI * unit(gen);
      const double r = o.spacing * (1 + o.annulus * unit(gen));
      const Eigen::Vector2d q = p + r * (root_inv * Eigen::Vector2d(std::cos(a), std::sin(a)));
      placed = try_add(q);
    }
    if (!placed) {
      active[pick] = active.back();
      active.pop_back();
    }
  }
  Eigen::Matrix2Xd out(2, static_cast<Eigen::Index>(interior.size()));
  for (std::size_t k = 0; k < interior.size(); ++k) out.col(k) = interior[k];
  return out;
}

}  // namespace homesh
