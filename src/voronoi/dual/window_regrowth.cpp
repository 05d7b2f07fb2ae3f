#include "voronoi/dual/window_regrowth.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>
#include <utility>

#include "voronoi/dual/refine_dual.h"
#include "voronoi/seeding/point_buckets.h"

namespace homesh {
namespace {

// The box [lo, hi].
struct Box {
  Eigen::Vector2d lo, hi;
  bool holds(const Eigen::Vector2d& p) const {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  }
  Box grown(double by) const { return {lo.array() - by, hi.array() + by}; }
};

int root(std::vector<int>& parent, int k) {
  while (parent[k] != k) k = parent[k] = parent[parent[k]];
  return k;
}

// The global dual with the window's triangles in `inner`: seeds (the
// global ones, then those the window's refinement added), triangles and
// their Voronoi vertices.
struct Merge {
  Eigen::Matrix2Xd seeds;
  std::vector<std::array<int, 3>> triangles;
  std::vector<Eigen::Vector2d> vertex;
  int nodes = 0;  // window grid nodes along the longer side
};

// The crystals of the seeds in `outer` grown again by refine_dual on a grid
// of spacing ds over it, seeds added only in `core` (their triangles then lie
// in `inner`), the segments inside protected from added seeds, and
// merged with the dual `at` (vertices `vertex`): its triangles whose vertex is
// outside `inner`, the window's inside, the seam mended within `band` of it.
Merge grow_window(const VoronoiProblem& problem, const RegrownDual& at,
                  const std::vector<Eigen::Vector2d>& vertex,
                  const std::vector<std::array<int, 2>>& segments,
                  const std::function<Eigen::VectorXd(const CartesianGrid&)>& domain_on,
                  const std::string& engine, const Box& core, const Box& inner, const Box& outer,
                  double ds, double band) {
  VoronoiProblem w;
  w.grid = CartesianGrid::stepped(outer.lo, outer.hi, ds);
  w.metric = problem.metric;
  w.contact = problem.contact;
  w.domain = domain_on(w.grid);
  std::vector<int> global;
  for (int s = 0; s < at.seeds.cols(); ++s)
    if (outer.holds(at.seeds.col(s))) global.push_back(s);
  w.seeds.resize(2, static_cast<Eigen::Index>(global.size()));
  for (std::size_t k = 0; k < global.size(); ++k) w.seeds.col(k) = at.seeds.col(global[k]);
  const int local = static_cast<int>(global.size());
  RefineOptions refine;
  refine.allowed = [core](const Eigen::Vector2d& p) { return core.holds(p); };
  std::vector<int> to_local(at.seeds.cols(), -1);
  for (int k = 0; k < local; ++k) to_local[global[k]] = k;
  for (const auto& [a, b] : segments)
    if (to_local[a] >= 0 && to_local[b] >= 0) refine.segments.push_back({to_local[a], to_local[b]});
  const RefinedDual r = refine_dual(w, engine, {}, refine);

  Merge out;
  out.seeds = at.seeds;
  out.nodes = std::max(w.grid.nx, w.grid.ny);
  const std::vector<std::array<int, 3>>& wt = r.result.dual.triangles;
  const auto to_global = [&](const std::array<int, 3>& t) {
    std::array<int, 3> g{};
    for (int k = 0; k < 3; ++k) {
      const int s = t[k];
      if (s >= local) {
        // A seed the window's refinement added: now a global seed.
        if (s >= static_cast<int>(global.size())) global.resize(s + 1, -1);
        if (global[s] < 0) {
          global[s] = static_cast<int>(out.seeds.cols());
          out.seeds.conservativeResize(2, out.seeds.cols() + 1);
          out.seeds.col(global[s]) = r.seeds.col(s);
        }
      }
      g[k] = global[s];
    }
    return g;
  };
  // The seam: each grid places a Voronoi vertex near the inner box's edge to
  // its own accuracy, so the same triangle may come from both or neither,
  // and near-cocircular seeds may be split the other way. A triangle is
  // taken unless one of its directed edges (counter-clockwise) is taken
  // already: the window's inside the box first, then the global ones outside
  // it (against the window's only: faults of the global dual are left to
  // conforming_triangulation), then the window's and the global ones within
  // `band` of the box's edge where a gap is left.
  std::set<std::pair<int, int>> window_edges, taken;
  const auto untaken = [](const std::set<std::pair<int, int>>& edges, const std::array<int, 3>& t) {
    for (int k = 0; k < 3; ++k)
      if (edges.count({t[k], t[(k + 1) % 3]})) return false;
    return true;
  };
  const auto take = [&](const std::array<int, 3>& t, const Eigen::Vector2d& v, bool window) {
    for (int k = 0; k < 3; ++k) {
      taken.insert({t[k], t[(k + 1) % 3]});
      if (window) window_edges.insert({t[k], t[(k + 1) % 3]});
    }
    out.triangles.push_back(t);
    out.vertex.push_back(v);
  };
  const Box near = inner.grown(band), deep = inner.grown(-band);
  for (std::size_t f = 0; f < wt.size(); ++f)
    if (inner.holds(r.result.dual.vertices.col(f)))
      take(to_global(wt[f]), r.result.dual.vertices.col(f), true);
  for (std::size_t f = 0; f < at.triangles.size(); ++f)
    if (!inner.holds(vertex[f]) && untaken(window_edges, at.triangles[f]))
      take(at.triangles[f], vertex[f], false);
  for (std::size_t f = 0; f < wt.size(); ++f) {
    const Eigen::Vector2d v = r.result.dual.vertices.col(f);
    if (inner.holds(v) || !near.holds(v)) continue;
    const std::array<int, 3> t = to_global(wt[f]);
    if (untaken(taken, t)) take(t, v, true);
  }
  for (std::size_t f = 0; f < at.triangles.size(); ++f)
    if (inner.holds(vertex[f]) && !deep.holds(vertex[f]) && untaken(taken, at.triangles[f]))
      take(at.triangles[f], vertex[f], false);
  return out;
}

}  // namespace

std::vector<std::vector<int>> cluster_spots(const std::vector<Eigen::Vector2d>& points,
                                            const std::vector<double>& sizes, double reach) {
  const int m = static_cast<int>(points.size());
  std::vector<int> parent(m);
  std::iota(parent.begin(), parent.end(), 0);
  if (m > 0) {
    Eigen::Vector2d lo = points[0], hi = lo;
    double largest = 0;
    for (int k = 0; k < m; ++k) {
      lo = lo.cwiseMin(points[k]);
      hi = hi.cwiseMax(points[k]);
      largest = std::max(largest, sizes[k]);
    }
    PointBuckets buckets(lo, hi, std::max(reach * largest, 1e-9 * (hi - lo).norm() + 1e-300));
    for (int a = 0; a < m; ++a) {
      buckets.all_of_near_index(points[a], reach * largest, [&](int b) {
        if ((points[a] - points[b]).norm() <= reach * std::max(sizes[a], sizes[b]))
          parent[root(parent, a)] = root(parent, b);
        return true;
      });
      buckets.add(points[a]);
    }
  }
  std::vector<std::vector<int>> members(m), out;
  for (int k = 0; k < m; ++k) members[root(parent, k)].push_back(k);
  for (auto& c : members)
    if (!c.empty()) out.push_back(std::move(c));
  return out;
}

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
                           const std::string& engine, const WindowOptions& o,
                           const std::vector<int>& fine) {
  RegrownDual out;
  out.seeds = problem.seeds;
  out.triangles = triangles;
  std::vector<Eigen::Vector2d> vertex(triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) vertex[f] = vertices.col(f);
  // With fine seeds, their windows alone (the segments still missed then
  // get windows of their own in another call).
  const std::vector<std::array<int, 2>> missed =
      fine.empty() ? missed_segments(segments, triangles) : std::vector<std::array<int, 2>>{};

  // Spots: the missed segments (their seed spacing, the metric's largest
  // size at their middle) and the fine seeds (the metric's smallest and
  // largest sizes there).
  struct Spot {
    Eigen::Vector2d lo, hi, middle;
    double spacing, size;
    int segment;  // into missed, or -1
  };
  std::vector<Spot> spots;
  for (std::size_t k = 0; k < missed.size(); ++k) {
    const Eigen::Vector2d a = problem.seeds.col(missed[k][0]), b = problem.seeds.col(missed[k][1]);
    const Eigen::Vector2d middle = 0.5 * (a + b);
    spots.push_back({a.cwiseMin(b), a.cwiseMax(b), middle, (a - b).norm(),
                     metric_max_speed(problem.metric.metric_at(middle)), static_cast<int>(k)});
  }
  for (const int s : fine) {
    const Eigen::Vector2d p = problem.seeds.col(s);
    const Eigen::Matrix2d M = problem.metric.metric_at(p);
    spots.push_back({p, p, p, metric_min_speed(M), metric_max_speed(M), -1});
  }
  std::vector<Eigen::Vector2d> middles;
  std::vector<double> sizes;
  for (const Spot& sp : spots) {
    middles.push_back(sp.middle);
    sizes.push_back(sp.size);
  }
  for (const std::vector<int>& members : cluster_spots(middles, sizes, 2 * o.pad)) {
    const Spot& first = spots[members.front()];
    Box box{first.lo, first.hi};
    double h_min = first.spacing, h_max = first.size;
    std::vector<std::array<int, 2>> cluster;
    // A segment missed though the global grid has `cells` cells along it
    // needs a window `finer` times finer; the other spots, `cells` cells per
    // spacing.
    bool resolved_miss = false;
    for (const int k : members) {
      resolved_miss = resolved_miss ||
                      (spots[k].segment >= 0 && spots[k].spacing >= o.cells * problem.grid.ds());
      box.lo = box.lo.cwiseMin(spots[k].lo);
      box.hi = box.hi.cwiseMax(spots[k].hi);
      h_min = std::min(h_min, spots[k].spacing);
      h_max = std::max(h_max, spots[k].size);
      if (spots[k].segment >= 0) cluster.push_back(missed[spots[k].segment]);
    }
    const Box inner = box.grown(o.pad * h_max), outer = inner.grown(o.pad * h_max);
    const double band = std::min(o.seam_cells * problem.grid.ds(), 0.5 * o.pad * h_max);
    const Box core = inner.grown(-0.5 * o.pad * h_max);
    const double extent = (outer.hi - outer.lo).maxCoeff();
    const double ds_min = std::max(extent / (o.max_nodes - 1), o.min_ds);
    const double ds_finer = resolved_miss ? problem.grid.ds() / o.finer : h_min / o.cells;
    double ds = std::max(std::min(h_min / o.cells, ds_finer), ds_min);
    if (ds >= 0.9 * problem.grid.ds()) continue;
    // The window grown at ds, then twice as fine while it still misses some
    // of the cluster's segments and the node cap allows; the attempt missing
    // the fewest (the finer on a tie) is merged.
    Merge best;
    int best_missed = std::numeric_limits<int>::max();
    for (;;) {
      Merge attempt = grow_window(problem, out, vertex, segments, domain_on, engine, core, inner,
                                  outer, ds, band);
      const int left = static_cast<int>(missed_segments(cluster, attempt.triangles).size());
      out.window_nodes = std::max(out.window_nodes, attempt.nodes);
      if (left <= best_missed) {
        best = std::move(attempt);
        best_missed = left;
      }
      if (left == 0 || ds <= ds_min) break;
      ds = std::max(0.5 * ds, ds_min);
      ++out.finer_windows;
    }
    ++out.windows;
    out.seeds = std::move(best.seeds);
    out.triangles = std::move(best.triangles);
    vertex = std::move(best.vertex);
  }
  out.vertices.resize(2, static_cast<Eigen::Index>(vertex.size()));
  for (std::size_t f = 0; f < vertex.size(); ++f) out.vertices.col(f) = vertex[f];
  return out;
}

}  // namespace homesh
