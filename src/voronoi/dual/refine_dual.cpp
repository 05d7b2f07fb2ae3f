#include "voronoi/dual/refine_dual.h"

#include <cmath>
#include <vector>

#include "voronoi/engines/fast_marching_engine.h"

namespace homesh {

Eigen::Matrix2Xd dual_faults(const Eigen::Matrix2Xd& seeds, const VoronoiDelaunay& v) {
  std::vector<Eigen::Vector2d> out;
  for (const int f : v.check.bad_triangles) out.push_back(v.dual.vertices.col(f));
  for (int k = 0; k < v.dual.defects.cols(); ++k) out.push_back(v.dual.defects.col(k));
  for (const auto& [a, b] : v.check.lone_edges) out.push_back(0.5 * (seeds.col(a) + seeds.col(b)));
  Eigen::Matrix2Xd m(2, static_cast<Eigen::Index>(out.size()));
  for (std::size_t k = 0; k < out.size(); ++k) m.col(k) = out[k];
  return m;
}

RefinedDual refine_dual(VoronoiProblem problem, const std::string& engine,
                        const VoronoiOptions& options, const RefineOptions& refine) {
  RefinedDual out;
  const CartesianGrid& g = problem.grid;
  const double clearance = refine.clearance_cells * g.ds();
  if (refine.max_rounds > 0) share_stencils(problem, engine);
  for (int round = 0;; ++round) {
    out.result = voronoi_delaunay(problem, engine, options);
    if (out.ok() || round == refine.max_rounds) break;
    const Eigen::Matrix2Xd faults = dual_faults(problem.seeds, out.result);
    std::vector<Eigen::Vector2d> added;
    for (int k = 0; k < faults.cols(); ++k) {
      const Eigen::Vector2d p = faults.col(k);
      if (refine.allowed && !refine.allowed(p)) continue;
      const Eigen::Vector2i n = g.nearest_node(p);
      const int node = g.index(n.x(), n.y());
      if (problem.domain.size() > 0 && problem.domain(node) > -clearance) continue;
      if (out.result.partition.labels(node) < 0) continue;
      bool clear = true;
      for (int s = 0; s < problem.seeds.cols() && clear; ++s)
        clear = (problem.seeds.col(s) - p).norm() >= clearance;
      for (const Eigen::Vector2d& q : added) clear = clear && (q - p).norm() >= clearance;
      for (const auto& [a, b] : refine.segments)
        clear = clear && (p - 0.5 * (problem.seeds.col(a) + problem.seeds.col(b))).norm() >=
                             0.5 * (problem.seeds.col(a) - problem.seeds.col(b)).norm() +
                                 refine.circle_cells * g.ds();
      if (clear) added.push_back(p);
    }
    if (added.empty()) break;
    const Eigen::Index S = problem.seeds.cols();
    problem.seeds.conservativeResize(2, S + static_cast<Eigen::Index>(added.size()));
    for (std::size_t k = 0; k < added.size(); ++k) {
      problem.seeds.col(S + k) = added[k];
      if (!problem.seed_metrics.empty()) {
        const Eigen::Vector2i n = g.nearest_node(added[k]);
        const int owner = out.result.partition.labels(g.index(n.x(), n.y()));
        problem.seed_metrics.push_back(problem.seed_metrics[owner]);
      }
    }
    out.added.push_back(static_cast<int>(added.size()));
  }
  out.seeds = problem.seeds;
  return out;
}

}  // namespace homesh
