#include "voronoi/seeding/lloyd_relaxation.h"

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/progress.h"
#include "voronoi/engines/fast_marching_engine.h"
#include "voronoi/engines/voronoi_engines.h"

namespace homesh {

Eigen::Matrix2Xd region_centroids(const CartesianGrid& g, const Eigen::VectorXi& labels, int seeds,
                                  const MetricField& metric,
                                  const std::vector<Eigen::Matrix2d>& seed_metrics) {
  // Per region: sum W(x) (symmetric: xx, xy, yy) and sum W(x) x.
  std::vector<Eigen::Matrix<double, 5, 1>> sum(seeds, Eigen::Matrix<double, 5, 1>::Zero());
  const bool constant = seed_metrics.empty() && metric.uniform();
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const int s = labels(g.index(i, j));
      if (s < 0 || s >= seeds) continue;
      const Eigen::Vector2d x = g.point(i, j);
      const Eigen::Matrix2d M = !seed_metrics.empty() ? seed_metrics[s]
                                : constant            ? metric.metric(0)
                                                      : metric.metric_at(x);
      const Eigen::Matrix2d W = centroid_weight(M);
      const Eigen::Vector2d Mx = W * x;
      sum[s] +=
          (Eigen::Matrix<double, 5, 1>() << W(0, 0), W(0, 1), W(1, 1), Mx.x(), Mx.y()).finished();
    }
  Eigen::Matrix2Xd z(2, seeds);
  for (int s = 0; s < seeds; ++s) {
    const auto& a = sum[s];
    Eigen::Matrix2d A;
    A << a(0), a(1), a(1), a(2);
    z.col(s) = a(0) > 0.0 ? Eigen::Vector2d(A.inverse() * Eigen::Vector2d(a(3), a(4)))
                          : Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  }
  return z;
}

void check_held(const std::vector<char>& held, Eigen::Index seeds) {
  if (!held.empty() && static_cast<Eigen::Index>(held.size()) != seeds)
    throw Error("voronoi: " + std::to_string(held.size()) + " held flags for " +
                std::to_string(seeds) + " seeds");
}

Eigen::Matrix2Xd lloyd_relaxation(VoronoiProblem problem, int fixed, const std::string& engine,
                                  const LloydOptions& options, const std::vector<char>& held) {
  const CartesianGrid& g = problem.grid;
  const double clearance = options.clearance_cells * g.ds();
  const int S = static_cast<int>(problem.seeds.cols());
  check_held(held, S);
  const int iterations = lloyd_iterations(options, false);
  Progress progress("iteration", iterations);
  share_stencils(problem, engine);
  for (int it = 0; it < iterations && fixed < S; ++it) {
    progress.update(it + 1);
    const CrystalPartition p = grow_crystals(problem, engine);
    const Eigen::Matrix2Xd z =
        region_centroids(g, p.labels, S, problem.metric, problem.seed_metrics);
    for (int s = fixed; s < S; ++s) {
      if (!held.empty() && held[s]) continue;
      const Eigen::Vector2d c = z.col(s);
      if (!c.allFinite()) continue;
      if (problem.domain.size() > 0 && bilinear_at(g, problem.domain, c) > -clearance) continue;
      bool clear = true;
      for (int o = 0; o < S && clear; ++o)
        clear = o == s || (problem.seeds.col(o) - c).norm() >= clearance;
      if (clear) problem.seeds.col(s) = c;
    }
  }
  return problem.seeds;
}

}  // namespace homesh
