#include "voronoi/window_regrowth.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <utility>

#include "voronoi/refine_dual.h"

namespace homesh {
namespace {

// The box [lo, hi].
struct Box {
  Eigen::Vector2d lo, hi;
  bool holds(const Eigen::Vector2d& p) const {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  }
  Box grown(double by) const {
    return {lo.array() - by, hi.array() + by};
  }
};

int root(std::vector<int>& parent, int k) {
  while (parent[k] != k) k = parent[k] = parent[parent[k]];
  return k;
}

}  // namespace

std::vector<std::array<int, 2>> missed_segments(const std::vector<std::array<int, 2>>& segments,
                                                const std::vector<std::array<int, 3>>& triangles) {
  std::set<std::pair<int, int>> edges;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  std::vector<std::array<int, 2>> out;
  for (const auto& [a, b] : segments)
    if (!edges.count(std::minmax(a, b))) out.push_back({a, b});
  return out;
}

RegrownDual regrow_windows(const VoronoiProblem& problem,
                           const std::vector<std::array<int, 3>>& triangles,
                           const Eigen::Matrix2Xd& vertices,
                           const std::vector<std::array<int, 2>>& segments,
                           const std::function<Eigen::VectorXd(const CartesianGrid&)>& domain_on,
                           const std::string& engine, const WindowOptions& o) {
  RegrownDual out;
  out.seeds = problem.seeds;
  out.triangles = triangles;
  std::vector<Eigen::Vector2d> vertex(triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) vertex[f] = vertices.col(f);
  const std::vector<std::array<int, 2>> missed = missed_segments(segments, triangles);

  // Clusters of missed segments: within 2 pads (in the metric's largest
  // size there) of each other.
  const int m = static_cast<int>(missed.size());
  const auto spacing = [&](int k) {
    return (problem.seeds.col(missed[k][0]) - problem.seeds.col(missed[k][1])).norm();
  };
  std::vector<Eigen::Vector2d> middle(m);
  std::vector<double> size(m);
  for (int k = 0; k < m; ++k) {
    middle[k] = 0.5 * (problem.seeds.col(missed[k][0]) + problem.seeds.col(missed[k][1]));
    size[k] = metric_max_speed(problem.metric.metric_at(middle[k]));
  }
  std::vector<int> parent(m);
  std::iota(parent.begin(), parent.end(), 0);
  for (int a = 0; a < m; ++a)
    for (int b = a + 1; b < m; ++b)
      if ((middle[a] - middle[b]).norm() <= 2 * o.pad * std::max(size[a], size[b]))
        parent[root(parent, a)] = root(parent, b);

  for (int c = 0; c < m; ++c) {
    if (root(parent, c) != c) continue;
    Box spots{middle[c], middle[c]};
    double h_min = spacing(c), h_max = size[c];
    for (int k = 0; k < m; ++k) {
      if (root(parent, k) != c) continue;
      for (const int s : missed[k]) {
        spots.lo = spots.lo.cwiseMin(problem.seeds.col(s));
        spots.hi = spots.hi.cwiseMax(problem.seeds.col(s));
      }
      h_min = std::min(h_min, spacing(k));
      h_max = std::max(h_max, size[k]);
    }
    const Box inner = spots.grown(o.pad * h_max), outer = inner.grown(o.pad * h_max);
    const double extent = (outer.hi - outer.lo).maxCoeff();
    const double ds = std::max(h_min / o.cells, extent / (o.max_nodes - 1));
    if (ds >= 0.9 * problem.grid.ds()) continue;

    VoronoiProblem w;
    w.grid.origin = outer.lo;
    w.grid.dx = w.grid.dy = ds;
    w.grid.nx = static_cast<int>(std::ceil((outer.hi.x() - outer.lo.x()) / ds)) + 1;
    w.grid.ny = static_cast<int>(std::ceil((outer.hi.y() - outer.lo.y()) / ds)) + 1;
    w.metric = problem.metric;
    w.contact = problem.contact;
    w.domain = domain_on(w.grid);
    std::vector<int> global;
    for (int s = 0; s < out.seeds.cols(); ++s)
      if (outer.holds(out.seeds.col(s))) global.push_back(s);
    w.seeds.resize(2, static_cast<Eigen::Index>(global.size()));
    for (std::size_t k = 0; k < global.size(); ++k) w.seeds.col(k) = out.seeds.col(global[k]);
    const int local = static_cast<int>(global.size());
    // The boundary segments inside the window protected from added seeds.
    RefineOptions refine;
    std::vector<int> to_local(out.seeds.cols(), -1);
    for (int k = 0; k < local; ++k) to_local[global[k]] = k;
    for (const auto& [a, b] : segments)
      if (to_local[a] >= 0 && to_local[b] >= 0)
        refine.segments.push_back({to_local[a], to_local[b]});
    const RefinedDual r = refine_dual(w, engine, {}, refine);
    ++out.windows;
    out.window_nodes = std::max(out.window_nodes, std::max(w.grid.nx, w.grid.ny));

    // The merge: the global triangles outside the inner box, the window's inside.
    std::vector<std::array<int, 3>> merged;
    std::vector<Eigen::Vector2d> merged_vertex;
    for (std::size_t f = 0; f < out.triangles.size(); ++f)
      if (!inner.holds(vertex[f])) {
        merged.push_back(out.triangles[f]);
        merged_vertex.push_back(vertex[f]);
      }
    const std::vector<std::array<int, 3>>& wt = r.result.dual.triangles;
    for (std::size_t f = 0; f < wt.size(); ++f) {
      const Eigen::Vector2d v = r.result.dual.vertices.col(f);
      if (!inner.holds(v)) continue;
      std::array<int, 3> t{};
      for (int k = 0; k < 3; ++k) {
        const int s = wt[f][k];
        if (s >= local) {
          // A seed the window's refinement added: now a global seed.
          if (s >= static_cast<int>(global.size())) global.resize(s + 1, -1);
          if (global[s] < 0) {
            global[s] = static_cast<int>(out.seeds.cols());
            out.seeds.conservativeResize(2, out.seeds.cols() + 1);
            out.seeds.col(global[s]) = r.seeds.col(s);
          }
        }
        t[k] = global[s];
      }
      merged.push_back(t);
      merged_vertex.push_back(v);
    }
    out.triangles = std::move(merged);
    vertex = std::move(merged_vertex);
  }
  return out;
}

}  // namespace homesh
