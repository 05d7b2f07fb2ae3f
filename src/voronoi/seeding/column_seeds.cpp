#include "voronoi/seeding/column_seeds.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>

#include "voronoi/seeding/spaced_seeds.h"

namespace homesh {
namespace {

// M's semi-axis ratio and its short axis (the eigenvector of the larger
// eigenvalue), turned to point along `along`.
struct Axes {
  double ratio;
  Eigen::Vector2d fine;
};
Axes axes_of(const Eigen::Matrix2d& M, const Eigen::Vector2d& along) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(M);
  Eigen::Vector2d e = eig.eigenvectors().col(1);
  if (e.dot(along) < 0) e = -e;
  return {std::sqrt(eig.eigenvalues()(1) / eig.eigenvalues()(0)), e};
}

double metric_ratio(const Eigen::Matrix2d& M) {
  const Eigen::Vector2d l =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(M, Eigen::EigenvaluesOnly).eigenvalues();
  return std::sqrt(l(1) / l(0));
}

Eigen::Vector2d left_normal(const Eigen::Vector2d& v) { return Eigen::Vector2d(-v.y(), v.x()); }

}  // namespace

// Advancing layers (Pirzadeh 1994) whose heights are unit steps of the metric.
ColumnSeeds metric_column_seeds(const CartesianGrid& g, const Eigen::VectorXd& domain,
                                const MetricField& metric, const Eigen::Matrix2Xd& boundary_seeds,
                                const std::vector<std::array<int, 2>>& segments,
                                const SeedingOptions& o, const std::vector<char>& sharp) {
  ColumnSeeds out;
  if (!(o.column_anisotropy > 0)) return out;
  const Eigen::Vector2d lo = g.origin, hi = g.point(g.nx - 1, g.ny - 1);
  const DomainTest test{g, domain};
  // The finest cells: the size along the walls (the searches reach that far).
  SpacedSeeds buckets(lo, hi, metric.min_speed() * metric.anisotropy(), metric);
  for (Eigen::Index k = 0; k < boundary_seeds.cols(); ++k) buckets.add(boundary_seeds.col(k));
  std::map<int, int> prev, next;
  for (const auto& [a, b] : segments) {
    next[a] = b;
    prev[b] = a;
  }
  const double cos_turn = std::cos(o.column_turn * M_PI / 180);
  struct Column {
    Eigen::Vector2d x, e, base;
    int fan;         // the corner's index for a fan's columns, else -1
    int seed;        // the boundary seed it starts from
    double spacing;  // from the other seeds, metric
  };
  std::vector<Column> columns;
  for (const auto& [s, q] : next) {
    const auto p = prev.find(s);
    if (p == prev.end()) continue;
    const Eigen::Vector2d x = boundary_seeds.col(s);
    const Eigen::Vector2d u = (x - boundary_seeds.col(p->second)).normalized();
    const Eigen::Vector2d v = (boundary_seeds.col(q) - x).normalized();
    // Spaced from the other seeds as the wall's seeds are: a column next to
    // a short segment (0.72 of the metric's unit by a corner of
    // slat_flap_bl_1e-4's slat) would otherwise stop at its first seed.
    const Eigen::Matrix2d Mx = metric.metric_at(x);
    const auto length = [&](int a, int b) {
      const Eigen::Vector2d d = boundary_seeds.col(b) - boundary_seeds.col(a);
      return std::sqrt(d.dot(Mx * d));
    };
    const double spacing = o.front_spacing * std::min({1.0, length(p->second, s), length(s, q)});
    if (!u.allFinite() || !v.allFinite()) continue;
    const bool corner = sharp.empty() ? !(u.dot(v) >= cos_turn) : sharp[s] != 0;
    if (corner) {
      // A corner. Where the wall turns away from the domain (a sharp
      // trailing edge, the domain's angle over 180 degrees), a fan: columns
      // along normals at most column_turn apart from one segment's to the
      // other's, which are not spaced from each other (their first seeds lie
      // within the first cell's height) and whose fine axis the layer metric
      // turns radially there (wall_layer.h).
      const double cross = u.x() * v.y() - u.y() * v.x();
      const double turn = std::acos(std::clamp(u.dot(v), -1.0, 1.0));
      if (cross >= 0) continue;  // the domain's angle below 180 degrees: none
      const int pieces = static_cast<int>(std::ceil(turn / (o.column_turn * M_PI / 180)));
      if (metric_ratio(Mx) < o.column_anisotropy) continue;
      for (int j = 0; j <= pieces; ++j) {
        const Eigen::Vector2d n = Eigen::Rotation2Dd(-turn * j / pieces) * left_normal(u);
        columns.push_back({x, n, x, s, s, spacing});
      }
      continue;
    }
    const Eigen::Vector2d n = (left_normal(u) + left_normal(v)).normalized();
    const Axes a = axes_of(Mx, n);
    if (a.ratio < o.column_anisotropy || a.fine.dot(n) < cos_turn) continue;
    columns.push_back({x, a.fine, x, -1, s, spacing});
  }
  out.columns = static_cast<int>(columns.size());
  for (const Column& c : columns)
    if (out.bases.empty() || out.bases.back() != c.seed) out.bases.push_back(c.seed);
  std::vector<Eigen::Vector2d> seeds;
  const double near_wall = 2 * g.ds();
  while (!columns.empty()) {
    std::vector<Column> alive;
    for (Column c : columns) {
      // A unit step in the metric at the step's midpoint (two fixed-point steps).
      double h = 1.0 / std::sqrt(c.e.dot(metric.metric_at(c.x) * c.e));
      for (int k = 0; k < 2; ++k)
        h = 1.0 / std::sqrt(c.e.dot(metric.metric_at(c.x + 0.5 * h * c.e) * c.e));
      const Eigen::Vector2d q = c.x + h * c.e;
      const Eigen::Matrix2d Mq = metric.metric_at(q);
      const Axes a = axes_of(Mq, c.e);
      if (a.ratio < o.column_end) continue;
      if ((q - c.base).norm() > near_wall && test.at(q) >= 0) continue;
      const double reach = 2.0 * o.front_spacing * metric_max_speed(Mq);
      if (!buckets.spaced(q, Mq, c.spacing, reach, c.fan)) continue;
      buckets.add(q, Mq, c.fan);
      seeds.push_back(q);
      out.in_fan.push_back(c.fan >= 0);
      // A fan's columns keep their direction: the metric's axis turns
      // between them (radial round the corner only beyond it).
      alive.push_back({q, c.fan >= 0 ? c.e : a.fine, c.base, c.fan, c.seed, c.spacing});
    }
    if (!alive.empty()) ++out.rows;
    columns = std::move(alive);
  }
  out.seeds.resize(2, static_cast<Eigen::Index>(seeds.size()));
  for (std::size_t k = 0; k < seeds.size(); ++k) out.seeds.col(k) = seeds[k];
  return out;
}

}  // namespace homesh
