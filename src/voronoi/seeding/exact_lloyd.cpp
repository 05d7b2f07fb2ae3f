#include "voronoi/seeding/exact_lloyd.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/progress.h"
#include "voronoi/dual/cgal_delaunay.h"

namespace homesh {
namespace {

constexpr double kStill = 1e-3;  // no seed moved by more than this share of its size: converged
constexpr int kSplit = 6;        // a clipped cell's fan triangles: kSplit^2 sub-triangles each

}  // namespace

Eigen::Matrix2Xd exact_lloyd(Eigen::Matrix2Xd seeds, int fixed, const MetricField& metric,
                             const std::function<double(const Eigen::Vector2d&)>& domain,
                             const LloydOptions& options, const std::vector<char>& held) {
  const Eigen::Index S = seeds.cols();
  check_held(held, S);
  const int iterations = lloyd_iterations(options, true);
  Progress progress("iteration", iterations);
  for (int it = 0; it < iterations && fixed < S; ++it) {
    progress.update(it + 1);
    const VoronoiCells cells = cgal_voronoi_cells(seeds);
    Eigen::Matrix2Xd next = seeds;
    double largest_move = 0.0;
    std::vector<double> area;  // of a cell's fan triangles
    for (Eigen::Index s = fixed; s < S; ++s) {
      const std::vector<Eigen::Vector2d>& cell = cells.vertices[s];
      if ((!held.empty() && held[s]) || cell.empty()) continue;
      // A cell that reaches outside the domain is integrated over its
      // inside only: each fan triangle in kSplit^2 sub-triangles, their
      // centroids weighed where inside (Du et al.'s constrained CVT, their
      // region clipped).
      const bool clipped = std::any_of(
          cell.begin(), cell.end(), [&](const Eigen::Vector2d& v) { return !(domain(v) < 0.0); });
      const Eigen::Vector2d p = seeds.col(s);
      Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
      Eigen::Vector2d b = Eigen::Vector2d::Zero();
      const auto add = [&](const Eigen::Vector2d& m, double w) {
        const Eigen::Matrix2d W = w * centroid_weight(metric.metric_at(m));
        A += W;
        b += W * m;
      };
      const std::size_t m = cell.size();
      if (!clipped) {
        // The edge-midpoint rule on each fan triangle (p, u_k, u_k+1): the
        // midpoint of spoke (p, u_k) is shared by the triangles on its two
        // sides and taken once, with a third of both their areas.
        area.resize(m);
        for (std::size_t k = 0; k < m; ++k) {
          const Eigen::Vector2d e = cell[k] - p, f = cell[(k + 1) % m] - p;
          area[k] = std::abs(e.x() * f.y() - e.y() * f.x()) / 2.0;
        }
        for (std::size_t k = 0; k < m; ++k) {
          add(0.5 * (p + cell[k]), (area[(k + m - 1) % m] + area[k]) / 3);
          add(0.5 * (cell[k] + cell[(k + 1) % m]), area[k] / 3);
        }
      }
      for (std::size_t k = 0; clipped && k < m; ++k) {
        const Eigen::Vector2d& u = cell[k];
        const Eigen::Vector2d& v = cell[(k + 1) % m];
        const Eigen::Vector2d e = u - p, f = v - p;
        const double fan_area = std::abs(e.x() * f.y() - e.y() * f.x()) / 2.0;
        const double sub = fan_area / (kSplit * kSplit);
        for (int i = 0; i < kSplit; ++i)
          for (int j = 0; i + j < kSplit; ++j) {
            // The upright sub-triangle at (i, j) and, but on the diagonal, the
            // inverted one beside it, by their centroids.
            const Eigen::Vector2d up = p + ((i + 1.0 / 3) * e + (j + 1.0 / 3) * f) / kSplit;
            if (domain(up) < 0.0) add(up, sub);
            if (i + j + 1 < kSplit) {
              const Eigen::Vector2d down = p + ((i + 2.0 / 3) * e + (j + 2.0 / 3) * f) / kSplit;
              if (domain(down) < 0.0) add(down, sub);
            }
          }
      }
      if (!(A.determinant() > 0.0)) continue;
      const Eigen::Vector2d z = A.inverse() * b;
      if (!z.allFinite()) continue;
      const double clearance = options.exact_clearance * metric_min_speed(metric.metric_at(z));
      if (!(domain(z) < -clearance)) continue;
      const bool clear = std::all_of(cells.neighbours[s].begin(), cells.neighbours[s].end(),
                                     [&](int o) { return (seeds.col(o) - z).norm() >= clearance; });
      if (!clear) continue;
      largest_move = std::max(largest_move, (z - p).norm() / metric_min_speed(metric.metric_at(p)));
      next.col(s) = z;
    }
    seeds = std::move(next);
    if (largest_move < kStill) break;
  }
  return seeds;
}

}  // namespace homesh
