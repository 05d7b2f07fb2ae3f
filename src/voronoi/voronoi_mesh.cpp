#include "voronoi/voronoi_mesh.h"

#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "core/check_mesh.h"
#include "core/error.h"
#include "core/progress.h"
#include "layers/edge_flips.h"
#include "voronoi/cleanup/metric_smoothing.h"
#include "voronoi/cleanup/valence_flips.h"
#include "voronoi/cleanup/valence_four.h"
#include "voronoi/cleanup/valence_three.h"
#include "voronoi/dual/cgal_constrained_delaunay.h"
#include "voronoi/dual/cgal_delaunay.h"
#include "voronoi/dual/conforming_dual.h"
#include "voronoi/dual/metric_delaunay.h"
#include "voronoi/dual/refine_dual.h"
#include "voronoi/dual/window_regrowth.h"
#include "voronoi/grid/loop_distance.h"
#include "voronoi/seeding/boundary_encroachment.h"
#include "voronoi/seeding/column_seeds.h"
#include "voronoi/seeding/exact_lloyd.h"

namespace homesh {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kCellsPerSize = 6.0;  // automatic grid: smallest size over this many cells
// ... with the exact dual, where only the seeding's inside tests use the grid:
// on the corpus 2 against 6 left the triangle counts within 1 % and the worst
// and mean ICN above Gmsh frontal's on every model, at about 0.85 of the time.
constexpr double kSeedCellsPerSize = 2.0;
constexpr int kGridMin = 200, kGridMax = 1500;
constexpr double kBandCells = 8.0;   // the domain's distance is exact this many cells out
constexpr int kLloydCoarsening = 2;  // Lloyd's iteration on a grid this many times coarser
// Valence flips (valence_flips.h) make no triangle worse than this (or than
// the worse of the two they replace). On the corpus (3 Dec 2026, after the
// smoothing) 0.7 raised the mean ICN on 39 of 41 models (median +0.001) and
// the worst on 28, lowering it on 10 by at most 0.008; 0.6 lowered the worst
// on 18 models by up to 0.089, 0.8 left almost no flip; flipping before the
// smoothing instead lowered the worst by up to 0.077.
constexpr double kValenceFloor = 0.7;
// Automatic growth grid: sized for all but this share of the seeds (by the
// metric's smallest size at them), windows round the finer ones
// (window_regrowth.h); the seeding grid alone is sized for the finest.
constexpr double kFineShare = 0.5;
constexpr double kFineGain = 0.8;  // ... if that grid has at most this times the nodes per side

// The metric's smallest size (semi-axis) at each seed.
std::vector<double> seed_sizes(const MetricField& metric, const Eigen::Matrix2Xd& seeds) {
  std::vector<double> h(seeds.cols());
  for (Eigen::Index s = 0; s < seeds.cols(); ++s)
    h[s] = metric_min_speed(metric.metric_at(seeds.col(s)));
  return h;
}

// The q-quantile of values (0 <= q <= 1).
double quantile(std::vector<double> values, double q) {
  const std::size_t k = static_cast<std::size_t>(q * (values.size() - 1));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string point_text(const Eigen::Vector2d& p) {
  std::ostringstream s;
  s.precision(10);
  s << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

// One surface's boundary: the seed loops (domain on the left) and the finely
// sampled polygons.
struct SurfaceLoops {
  std::vector<std::array<int, 2>> segments;  // boundary seed pairs
  std::vector<Eigen::Matrix2Xd> polygons;
  Eigen::Vector2d lo, hi;
};

SurfaceLoops surface_loops(const SeededBoundary& b, const SurfaceBoundary& s) {
  SurfaceLoops out;
  std::vector<std::vector<std::array<int, 2>>> loop_segments;
  for (const auto& loop : s.loops) {
    std::vector<int> seeds;
    std::vector<Eigen::Vector2d> pts;
    for (const LoopCurve& c : loop) {
      std::vector<int> on = b.curve_seeds.at(c.tag);
      const Eigen::Matrix2Xd& x = b.curve_samples.at(c.tag);
      if (c.reversed) std::reverse(on.begin(), on.end());
      seeds.insert(seeds.end(), on.begin(), on.end() - 1);
      for (Eigen::Index k = 0; k + 1 < x.cols(); ++k)
        pts.push_back(x.col(c.reversed ? x.cols() - 1 - k : k));
    }
    loop_segments.emplace_back();
    for (std::size_t k = 0; k < seeds.size(); ++k)
      loop_segments.back().push_back({seeds[k], seeds[(k + 1) % seeds.size()]});
    Eigen::Matrix2Xd poly(2, static_cast<Eigen::Index>(pts.size()));
    for (std::size_t k = 0; k < pts.size(); ++k) poly.col(k) = pts[k];
    out.polygons.push_back(poly);
  }
  // The domain on the left of every segment: a loop inside an even number of
  // the others runs counter-clockwise, inside an odd number (a hole)
  // clockwise, whatever Gmsh's orientation of the surface.
  for (std::size_t l = 0; l < out.polygons.size(); ++l) {
    const Eigen::Matrix2Xd& p = out.polygons[l];
    double area = 0.0;
    for (Eigen::Index k = 0; k < p.cols(); ++k) {
      const Eigen::Vector2d a = p.col(k), c = p.col((k + 1) % p.cols());
      area += 0.5 * (a.x() * c.y() - a.y() * c.x());
    }
    int depth = 0;
    for (std::size_t o = 0; o < out.polygons.size(); ++o)
      depth += o != l && inside_loops({out.polygons[o]}, p.col(0));
    // A flipped loop is also walked backwards, so that each segment starts
    // where the one before it ended (the front rows follow these chains).
    const bool flip = (area > 0) == (depth % 2 == 1);
    if (flip)
      for (auto it = loop_segments[l].rbegin(); it != loop_segments[l].rend(); ++it)
        out.segments.push_back({(*it)[1], (*it)[0]});
    else
      out.segments.insert(out.segments.end(), loop_segments[l].begin(), loop_segments[l].end());
  }
  out.lo = out.polygons.front().rowwise().minCoeff();
  out.hi = out.polygons.front().rowwise().maxCoeff();
  for (const auto& p : out.polygons) {
    out.lo = out.lo.cwiseMin(p.rowwise().minCoeff());
    out.hi = out.hi.cwiseMax(p.rowwise().maxCoeff());
  }
  return out;
}

// One flag per node: 1 for an interior node (on a surface) not held (in a
// column across an anisotropic wall), which the clean-up may move or remove.
std::vector<char> free_nodes(const std::vector<NodeClass>& node_class,
                             const std::vector<char>& held) {
  std::vector<char> out(node_class.size());
  for (std::size_t k = 0; k < node_class.size(); ++k) out[k] = node_class[k].dim == 2 && !held[k];
  return out;
}

// free_nodes on m, less the nodes of the triangles at a held node: the
// smoothing judges a move by the metric at its triangles' centroids, which
// near a 1500:1 layer favour triangles reaching into it (it moved seeds from
// above the columns to within the first cell of the wall on
// circle_bl_1e-5_fine: curve:p=3 0.81 against 0.999 without).
std::vector<char> movable_nodes(const Mesh& m, const std::vector<char>& held) {
  std::vector<char> out = free_nodes(m.node_class, held);
  for (int t = 0; t < m.num_triangles(); ++t)
    if (held[m.tri(0, t)] || held[m.tri(1, t)] || held[m.tri(2, t)])
      for (int k = 0; k < 3; ++k) out[m.tri(k, t)] = 0;
  return out;
}

// Per boundary seed: the CAD's curves turn by more than `degrees` there (a
// model point where their end tangents, from the fine samples, are not
// opposite within it); the seeds inside a curve are smooth.
std::vector<char> sharp_seeds(const SeededBoundary& b, double degrees) {
  std::map<int, std::vector<Eigen::Vector2d>> away;  // unit tangents leaving the seed
  for (const auto& [tag, on] : b.curve_seeds) {
    const Eigen::Matrix2Xd& x = b.curve_samples.at(tag);
    if (on.empty() || x.cols() < 2) continue;
    const Eigen::Index n = x.cols();
    away[on.front()].push_back((x.col(1) - x.col(0)).normalized());
    away[on.back()].push_back((x.col(n - 2) - x.col(n - 1)).normalized());
  }
  std::vector<char> out(b.seeds.cols(), 0);
  for (const auto& [s, t] : away)
    out[s] = t.size() != 2 || !(t[0].dot(t[1]) <= -std::cos(degrees * M_PI / 180));
  return out;
}

// Drops nodes `gone` (ascending; in no triangle, line or point) from m,
// renumbering the others (and their flags `held`) in order.
void drop_nodes(Mesh& m, const std::vector<int>& gone, std::vector<char>& held) {
  std::vector<int> to(m.x.cols(), -1);
  int count = 0;
  for (int k = 0, g = 0; k < static_cast<int>(to.size()); ++k)
    if (g < static_cast<int>(gone.size()) && gone[g] == k)
      ++g;
    else
      to[k] = count++;
  Eigen::Matrix2Xd x(2, count);
  std::vector<NodeClass> node_class(count);
  std::vector<char> kept(count);
  for (std::size_t k = 0; k < to.size(); ++k)
    if (to[k] >= 0) {
      x.col(to[k]) = m.x.col(static_cast<Eigen::Index>(k));
      node_class[to[k]] = m.node_class[k];
      kept[to[k]] = held[k];
    }
  held = std::move(kept);
  m.x = std::move(x);
  m.node_class = std::move(node_class);
  for (Eigen::MatrixXi* elements : {&m.tri, &m.line})
    for (Eigen::Index e = 0; e < elements->size(); ++e) (*elements)(e) = to[(*elements)(e)];
  for (int& p : m.point_node) p = to[p];
}

// Lloyd's iteration on the seeds `free` of problem p (its metric and seeds)
// in windows round their clusters, as window_regrowth.h places them, each on
// a grid of kCellsPerSize cells per smallest size there, no finer than
// min_ds; the other seeds in a window stay. Returns all the seeds.
Eigen::Matrix2Xd lloyd_in_windows(const VoronoiProblem& p, const std::vector<int>& free,
                                  const SurfaceLoops& loops, double min_ds,
                                  const std::string& engine, const LloydOptions& lloyd) {
  const WindowOptions w;
  Eigen::Matrix2Xd seeds = p.seeds;
  std::vector<Eigen::Vector2d> points;
  std::vector<double> size, smallest;
  for (const int s : free) {
    const Eigen::Matrix2d M = p.metric.metric_at(seeds.col(s));
    points.push_back(seeds.col(s));
    size.push_back(metric_max_speed(M));
    smallest.push_back(metric_min_speed(M));
  }
  for (const std::vector<int>& members : cluster_spots(points, size, 2 * w.pad)) {
    Eigen::Vector2d lo = points[members[0]], hi = lo;
    double h_min = smallest[members[0]], h_max = size[members[0]];
    for (const int k : members) {
      lo = lo.cwiseMin(points[k]);
      hi = hi.cwiseMax(points[k]);
      h_min = std::min(h_min, smallest[k]);
      h_max = std::max(h_max, size[k]);
    }
    // The window: the seeds' box grown by 2 pads of the largest size, so
    // that the regions of the seeds that move lie in it.
    lo.array() -= 2 * w.pad * h_max;
    hi.array() += 2 * w.pad * h_max;
    const double extent = (hi - lo).maxCoeff();
    const double ds = std::max({h_min / kCellsPerSize, min_ds, extent / (w.max_nodes - 1)});
    VoronoiProblem win;
    win.metric = p.metric;
    win.grid = CartesianGrid::stepped(lo, hi, ds);
    win.domain = loop_signed_distance(win.grid, loops.polygons, kBandCells * ds);
    std::vector<int> local;
    std::vector<char> held;
    std::vector<char> moves(seeds.cols(), 0);
    for (const int k : members) moves[free[k]] = 1;
    for (Eigen::Index s = 0; s < seeds.cols(); ++s) {
      const Eigen::Vector2d x = seeds.col(s);
      if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any()) continue;
      local.push_back(static_cast<int>(s));
      held.push_back(moves[s] ? 0 : 1);
    }
    win.seeds = seeds(Eigen::all, local);
    const Eigen::Matrix2Xd moved = lloyd_relaxation(win, 0, engine, lloyd, held);
    for (std::size_t k = 0; k < local.size(); ++k) seeds.col(local[k]) = moved.col(k);
  }
  return seeds;
}

// Interior seeds from a file: those inside this surface's polygons, each
// checked against the boundary and the other seeds (within one cell of
// another seed is coincident on the grid).
Eigen::Matrix2Xd file_seeds(const std::string& path, const SeedList& list, const SurfaceLoops& s,
                            const CartesianGrid& g, const Eigen::VectorXd& domain,
                            const Eigen::Matrix2Xd& boundary, std::vector<char>& used) {
  std::vector<Eigen::Vector2d> out;
  std::vector<int> lines;
  for (Eigen::Index k = 0; k < list.points.cols(); ++k) {
    const Eigen::Vector2d p = list.points.col(k);
    if (!inside_loops(s.polygons, p)) continue;
    used[k] = 1;
    const std::string at = path + ":" + std::to_string(list.lines[k]) + ": seed " + point_text(p);
    const Eigen::Vector2i n = g.nearest_node(p);
    if (domain(g.index(n.x(), n.y())) > -g.ds())
      throw Error(at + " lies within one grid cell of the boundary");
    for (Eigen::Index b = 0; b < boundary.cols(); ++b)
      if ((boundary.col(b) - p).norm() < g.ds())
        throw Error(at + " is within one grid cell of a boundary seed");
    for (std::size_t q = 0; q < out.size(); ++q)
      if ((out[q] - p).norm() < g.ds())
        throw Error(at + (out[q] == p ? " coincides with" : " is within one grid cell of") +
                    " the seed on line " + std::to_string(lines[q]));
    out.push_back(p);
    lines.push_back(list.lines[k]);
  }
  Eigen::Matrix2Xd m(2, static_cast<Eigen::Index>(out.size()));
  for (std::size_t k = 0; k < out.size(); ++k) m.col(k) = out[k];
  return m;
}

// The triangles of one surface, in its local seed numbering.
struct SurfaceMesh {
  Eigen::Matrix2Xd seeds;  // the surface's boundary seeds first, then its interior ones
  std::vector<std::array<int, 3>> triangles;
  std::vector<char> held = {};  // per seed: in a column (the clean-up leaves it)
};

// Thesis Ch 2 on one surface: seeds, growth, dual, regrowth, conforming fill.
SurfaceMesh mesh_surface(const SurfaceLoops& loops, const Eigen::Matrix2Xd& bseeds,
                         const std::vector<std::array<int, 2>>& segments, const MetricField& metric,
                         const VoronoiMeshOptions& o, const std::vector<char>& sharp,
                         std::vector<char>& list_used, VoronoiSurfaceReport& rep) {
  const double extent = (loops.hi - loops.lo).maxCoeff();
  const bool isotropic = metric.anisotropy() <= kIsotropic;
  const bool exact_dual = o.dual == "exact";
  // The exact dual needs the grid only for the seeds' inside tests: sized by
  // the smallest size along the walls (an anisotropic metric's columns go
  // their first cells without the grid).
  const double cells_per_size = exact_dual ? kSeedCellsPerSize : kCellsPerSize;
  const double grid_size =
      exact_dual ? metric.min_speed() * metric.anisotropy() : metric.min_speed();
  const int n = o.grid > 0
                    ? o.grid
                    : std::clamp(static_cast<int>(std::ceil(extent / (grid_size / cells_per_size))),
                                 kGridMin, kGridMax);
  VoronoiProblem p;
  p.grid = CartesianGrid::covering(loops.lo, loops.hi, n, 3);
  p.metric = metric;
  p.domain = loop_signed_distance(p.grid, loops.polygons, kBandCells * p.grid.ds());
  rep.grid = p.grid;
  rep.boundary_seeds = bseeds.cols();

  const auto seeding = Clock::now();
  // Automatic seeds: the front rows advancing from the boundary segments,
  // then Poisson-disc seeds spaced from both where the fronts meet.
  const bool auto_seeds = o.seed_list == nullptr;
  // Where the metric is anisotropic at the walls, columns across them first
  // (column_seeds.h), then the rows where there are none.
  const ColumnSeeds columns =
      auto_seeds && !isotropic
          ? metric_column_seeds(p.grid, p.domain, metric, bseeds, segments, o.seeding, sharp)
          : ColumnSeeds{};
  Eigen::Matrix2Xd walls(2, bseeds.cols() + columns.seeds.cols());
  walls << bseeds, columns.seeds;
  // The rows and corner seeds only on the segments no column stands on:
  // across an anisotropic wall a row's apexes and the corner seeds (a wall
  // turning by 2 degrees is a corner of 75-140 degrees in a 1500:1 metric)
  // fall between the columns (circle_bl_1e-5_fine: curve:p=3 0.34, without
  // them 0.999).
  std::vector<std::array<int, 2>> open_segments;
  for (const auto& sg : segments)
    if (!std::binary_search(columns.bases.begin(), columns.bases.end(), sg[0]) &&
        !std::binary_search(columns.bases.begin(), columns.bases.end(), sg[1]))
      open_segments.push_back(sg);
  const FrontSeeds front =
      auto_seeds ? metric_front_seeds(p.grid, p.domain, metric, walls, open_segments, o.seeding)
                 : FrontSeeds{};
  Eigen::Matrix2Xd held(2, walls.cols() + front.seeds.cols());
  held << walls, front.seeds;
  rep.column_seeds = columns.seeds.cols();
  rep.columns = columns.columns;
  rep.column_rows = columns.rows;
  // Lloyd's iteration holds the columns and the first row (and the corner
  // seeds) and relaxes the others where the fronts meet; rows are its fixed
  // points elsewhere, but the collisions need it.
  const Eigen::Index hold = walls.cols() + front.first_row;
  const Eigen::Matrix2Xd interior =
      auto_seeds
          ? metric_interior_seeds(p.grid, p.domain, metric, held, o.seeding)
          : file_seeds(o.seed_path, *o.seed_list, loops, p.grid, p.domain, bseeds, list_used);
  p.seeds.resize(2, held.cols() + interior.cols());
  p.seeds << held, interior;
  // The growth grid: with o.fine_windows, sized for all but the finest
  // kFineShare of the seeds, which get windows of their own below.
  const std::vector<double> h_seed = seed_sizes(metric, p.seeds);
  int n_growth = n;
  if (o.grid == 0 && o.fine_windows && !h_seed.empty()) {
    const int n_share = std::clamp(
        static_cast<int>(std::ceil(extent / (quantile(h_seed, kFineShare) / kCellsPerSize))),
        kGridMin, kGridMax);
    if (n_share <= kFineGain * n) n_growth = n_share;
  }
  const CartesianGrid growth_grid = CartesianGrid::covering(loops.lo, loops.hi, n_growth, 3);
  Progress phase("phase", 3);
  // With columns, no automatic Lloyd iterations: the exact cells' centroids,
  // weighted by sqrt(det M), pull seeds from above the layer down into the
  // gaps between columns (circle_bl_1e-5_fine: curve:p=3 0.18 with 15, 0.999
  // without).
  LloydOptions lloyd = o.lloyd;
  if (columns.seeds.cols() > 0 && lloyd.iterations == kAutoIterations) lloyd.iterations = 0;
  const bool exact =
      auto_seeds && lloyd.iterations != 0 &&
      (lloyd.cells == "exact" || (lloyd.cells == "auto" && (isotropic || exact_dual)));
  rep.exact_lloyd = exact;
  rep.lloyd_iterations = auto_seeds ? lloyd_iterations(lloyd, exact) : 0;
  if (exact) {
    phase.update(0, "Lloyd's iteration on the seeds' exact cells");
    p.seeds = exact_lloyd(
        p.seeds, static_cast<int>(hold), metric,
        [&p](const Eigen::Vector2d& x) { return bilinear_at(p.grid, p.domain, x); }, lloyd);
  } else if (auto_seeds && lloyd.iterations != 0) {
    phase.update(0, "Lloyd's iteration on the seeds");
    // On a grid kLloydCoarsening times coarser: a centroid needs far fewer
    // cells per region than a dual triangle does. Seeds finer than that grid
    // resolves stay (rows from the walls, where they are Lloyd's fixed points).
    VoronoiProblem coarse = p;
    coarse.grid = CartesianGrid::covering(loops.lo, loops.hi,
                                          std::max(kGridMin, n_growth / kLloydCoarsening), 3);
    coarse.domain =
        loop_signed_distance(coarse.grid, loops.polygons, kBandCells * coarse.grid.ds());
    std::vector<char> held_fine(p.seeds.cols(), 0);
    if (n_growth < n)
      for (std::size_t s = 0; s < h_seed.size(); ++s)
        held_fine[s] = h_seed[s] < kCellsPerSize * coarse.grid.ds();
    p.seeds = lloyd_relaxation(coarse, static_cast<int>(hold), o.engine, lloyd, held_fine);
    std::vector<int> fine_free;
    for (Eigen::Index s = hold; s < p.seeds.cols(); ++s)
      if (held_fine[s]) fine_free.push_back(static_cast<int>(s));
    p.seeds =
        lloyd_in_windows(p, fine_free, loops, kLloydCoarsening * p.grid.ds(), o.engine, lloyd);
  }
  // Automatic seeds inside a boundary segment's diametral circle go: that
  // segment could be in no dual.
  std::vector<int> encroaching;
  std::vector<char> in_column;
  if (auto_seeds) {
    // In the metric where it is anisotropic: a column's seeds sit well inside
    // the Euclidean circles of its wall's segments. The fans' seeds stay: the
    // constrained triangulation keeps every segment, and a fan's first seeds
    // lie within the ellipse that the metric of a segment's midpoint draws
    // round the segment by a sharp corner (slat_flap_bl_1e-4: without them
    // curving failed at 84 %; keeping every column's seed lowered the p = 3
    // worst at three leading edges, naca0006_bl_1e-4 0.89 -> 0.69).
    encroaching = encroaching_seeds(p.seeds, static_cast<int>(bseeds.cols()), segments,
                                    isotropic ? nullptr : &metric);
    encroaching.erase(std::remove_if(encroaching.begin(), encroaching.end(),
                                     [&](int k) {
                                       return k < walls.cols() && columns.in_fan[k - bseeds.cols()];
                                     }),
                      encroaching.end());
    std::vector<int> keep;
    for (int k = 0, e = 0; k < p.seeds.cols(); ++k)
      if (e < static_cast<int>(encroaching.size()) && encroaching[e] == k)
        ++e;
      else
        keep.push_back(k);
    p.seeds = Eigen::Matrix2Xd(p.seeds(Eigen::all, keep));
    for (const int k : keep) in_column.push_back(k >= bseeds.cols() && k < walls.cols());
  }
  rep.encroaching_dropped = static_cast<long>(encroaching.size());
  rep.front_seeds =
      held.cols() - bseeds.cols() -
      std::count_if(encroaching.begin(), encroaching.end(), [&](int k) { return k < held.cols(); });
  rep.interior_seeds = p.seeds.cols() - bseeds.cols() - rep.front_seeds;
  rep.seeding_seconds = seconds_since(seeding);

  rep.exact_dual = exact_dual;
  if (exact_dual) {
    phase.update(1, "the Delaunay triangulation of " + std::to_string(p.seeds.cols()) + " seeds");
    const auto growth = Clock::now();
    // The Delaunay triangulation constrained by the boundary segments, in
    // the domain: its Delaunay triangles are dual triangles, the others
    // (at a boundary segment some seed sees first) the fill.
    std::vector<std::array<int, 3>> triangles = cgal_constrained_triangles(p.seeds, segments, {});
    rep.dual_checked = true;
    rep.segments = static_cast<long>(segments.size());
    if (!isotropic) {
      // Anisotropic: Lawson's flips to the Delaunay triangulation in the
      // metric (metric_delaunay.h); an edge left not locally Delaunay makes
      // its triangles the fill.
      const MetricDelaunay d = metric_delaunay_flips(p.seeds, triangles, segments, metric);
      rep.metric_dual = true;
      rep.metric_flips = d.flips;
      rep.dual_size = static_cast<long>(triangles.size());
      rep.filled = d.not_delaunay;
      rep.from_dual = rep.dual_size - rep.filled;
      rep.growth_seconds = seconds_since(growth);
      return {p.seeds, std::move(triangles), std::move(in_column)};
    }
    const std::vector<std::array<int, 3>> dual = cgal_delaunay_triangles(p.seeds);
    rep.dual_size = static_cast<long>(dual.size());
    rep.missed_segments = rep.boundary_missed =
        static_cast<long>(missed_segments(segments, dual).size());
    for (const auto& t : triangles)
      ++(std::binary_search(dual.begin(), dual.end(), t) ? rep.from_dual : rep.filled);
    rep.growth_seconds = seconds_since(growth);
    return {p.seeds, std::move(triangles)};
  }
  phase.update(1, "growing " + std::to_string(p.seeds.cols()) + " crystals");
  const auto growth = Clock::now();
  // On the growth grid, the seeds it does not resolve are `fine`: no seed is
  // added near them (the faults there are the grid's), windows grow them.
  std::vector<int> fine;
  RefineOptions refine;
  refine.segments = segments;
  const double seeding_ds = p.grid.ds();
  if (n_growth < n) {
    p.grid = growth_grid;
    p.domain = loop_signed_distance(p.grid, loops.polygons, kBandCells * p.grid.ds());
    const double resolved = kCellsPerSize * p.grid.ds();
    const std::vector<double> h_moved = seed_sizes(metric, p.seeds);  // after Lloyd's moves
    for (std::size_t s = 0; s < h_moved.size(); ++s)
      if (h_moved[s] < resolved) fine.push_back(static_cast<int>(s));
    refine.allowed = [&metric, resolved](const Eigen::Vector2d& x) {
      return metric_min_speed(metric.metric_at(x)) >= 1.5 * resolved;
    };
  }
  rep.fine_seeds = static_cast<long>(fine.size());
  rep.grid = p.grid;
  const RefinedDual r = refine_dual(p, o.engine, {}, refine);
  rep.growth_seconds = seconds_since(growth);
  rep.dual_size = static_cast<long>(r.result.dual.triangles.size());
  rep.dual_checked = r.ok();
  rep.refinement_rounds = static_cast<long>(r.added.size());
  for (const int a : r.added) rep.refined_seeds += a;
  // Where the dual misses the boundary, a finer grid round the spot.
  p.seeds = r.seeds;
  phase.update(2, "regrowing where the grid is too coarse for the seeds");
  const auto domain_on = [&](const CartesianGrid& g) {
    return loop_signed_distance(g, loops.polygons, kBandCells * g.ds());
  };
  RegrownDual w;
  rep.missed_segments =
      static_cast<long>(missed_segments(segments, r.result.dual.triangles).size());
  if (fine.empty()) {
    w = regrow_windows(p, r.result.dual.triangles, r.result.dual.vertices, segments, domain_on,
                       o.engine);
  } else {
    // Windows round the fine seeds, then round the segments still missed.
    // No finer than the seeding grid, sized for the finest seed (and capped).
    WindowOptions finest;
    finest.min_ds = seeding_ds;
    const RegrownDual f = regrow_windows(p, r.result.dual.triangles, r.result.dual.vertices,
                                         segments, domain_on, o.engine, finest, fine);
    VoronoiProblem merged = p;
    merged.seeds = f.seeds;
    w = regrow_windows(merged, f.triangles, f.vertices, segments, domain_on, o.engine);
    w.windows += f.windows;
    w.window_nodes = std::max(w.window_nodes, f.window_nodes);
    w.finer_windows += f.finer_windows;
    rep.fine_windows = f.windows;
    rep.missed_segments = static_cast<long>(missed_segments(segments, f.triangles).size());
  }
  rep.windows = w.windows;
  if (w.windows > 0) {
    rep.window_nodes = w.window_nodes;
    rep.finer_windows = w.finer_windows;
    rep.regrown_seeds = w.seeds.cols() - r.seeds.cols();
  }
  const ConformingTriangulation c = conforming_triangulation(w.seeds, segments, w.triangles);
  rep.segments = static_cast<long>(segments.size());
  rep.boundary_missed = c.boundary_missed;
  rep.dual_dropped = c.dual_dropped;
  rep.from_dual = c.from_dual;
  rep.filled = c.filled;
  return {w.seeds, c.triangles};
}

}  // namespace

// Thesis Ch 2 (Sections 2.3-2.5) on every surface, the boundary seeds shared.
Mesh voronoi_mesh(const SeededBoundary& boundary, const MetricField& metric,
                  const VoronoiMeshOptions& o, VoronoiReport* report) {
  if (o.lloyd.cells != "auto" && o.lloyd.cells != "exact" && o.lloyd.cells != "grown")
    throw Error("voronoi: Lloyd's cells '" + o.lloyd.cells + "' are none of auto, exact, grown");
  if (o.dual != "exact" && o.dual != "grown")
    throw Error("voronoi: the dual '" + o.dual + "' is none of exact, grown");
  VoronoiReport local;
  VoronoiReport& rep = report ? *report : local;
  rep = {};
  std::vector<char> list_used(o.seed_list ? o.seed_list->points.cols() : 0, 0);

  std::vector<Eigen::Vector2d> nodes;
  for (Eigen::Index k = 0; k < boundary.seeds.cols(); ++k) nodes.push_back(boundary.seeds.col(k));
  std::vector<NodeClass> node_class = boundary.classes;
  std::vector<char> held(nodes.size(), 0);  // column seeds: the clean-up leaves them
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> triangle_surface;
  const std::vector<char> sharp = sharp_seeds(boundary, o.seeding.column_turn);
  for (const SurfaceBoundary& surface : boundary.surfaces) {
    const SurfaceLoops loops = surface_loops(boundary, surface);
    // This surface's boundary seeds, renumbered from 0.
    std::vector<int> local_to_node;
    std::map<int, int> node_to_local;
    for (const auto& [a, b] : loops.segments)
      for (const int s : {a, b})
        if (!node_to_local.count(s)) {
          node_to_local[s] = static_cast<int>(local_to_node.size());
          local_to_node.push_back(s);
        }
    Eigen::Matrix2Xd bseeds(2, static_cast<Eigen::Index>(local_to_node.size()));
    for (std::size_t k = 0; k < local_to_node.size(); ++k)
      bseeds.col(k) = boundary.seeds.col(local_to_node[k]);
    std::vector<std::array<int, 2>> segments;
    for (const auto& [a, b] : loops.segments)
      segments.push_back({node_to_local[a], node_to_local[b]});

    VoronoiSurfaceReport sr;
    sr.tag = surface.tag;
    std::vector<char> local_sharp;
    for (const int k : local_to_node) local_sharp.push_back(sharp[k]);
    const SurfaceMesh sm =
        mesh_surface(loops, bseeds, segments, metric, o, local_sharp, list_used, sr);
    rep.dual_triangles += static_cast<int>(sr.from_dual);
    rep.filled_triangles += static_cast<int>(sr.filled);
    rep.refined_seeds += static_cast<int>(sr.refined_seeds);
    rep.surfaces.push_back(sr);

    // Interior and added seeds become nodes of the surface.
    std::vector<int> to_node(local_to_node);
    for (Eigen::Index k = bseeds.cols(); k < sm.seeds.cols(); ++k) {
      to_node.push_back(static_cast<int>(nodes.size()));
      nodes.push_back(sm.seeds.col(k));
      node_class.push_back({2, surface.tag, std::numeric_limits<double>::quiet_NaN()});
      held.push_back(k < static_cast<Eigen::Index>(sm.held.size()) && sm.held[k]);
    }
    for (const auto& t : sm.triangles) {
      triangles.push_back({to_node[t[0]], to_node[t[1]], to_node[t[2]]});
      triangle_surface.push_back(surface.tag);
    }
  }
  if (o.seed_list)
    for (Eigen::Index k = 0; k < o.seed_list->points.cols(); ++k)
      if (!list_used[k])
        throw Error(o.seed_path + ":" + std::to_string(o.seed_list->lines[k]) + ": seed " +
                    point_text(o.seed_list->points.col(k)) + " lies outside the domain");

  // Topological clean-up: the interior nodes of three triangles go.
  if (o.cleanup) {
    rep.valence_three =
        remove_valence_three(triangles, triangle_surface, free_nodes(node_class, held));
  }
  // Nodes no triangle uses (interior seeds cut off by a boundary chord) go.
  std::vector<int> renumber(nodes.size(), -1);
  for (const auto& t : triangles)
    for (const int v : t) renumber[v] = 0;
  for (std::size_t k = 0; k < boundary.classes.size(); ++k) renumber[k] = 0;
  int count = 0;
  for (int& r : renumber) r = r < 0 ? (++rep.dropped_seeds, -1) : count++;
  rep.dropped_seeds -= rep.valence_three;
  Mesh m;
  m.order = 1;
  m.x.resize(2, count);
  m.node_class.resize(count);
  std::vector<char> m_held(count, 0);
  for (std::size_t k = 0; k < nodes.size(); ++k)
    if (renumber[k] >= 0) {
      m.x.col(renumber[k]) = nodes[k];
      m.node_class[renumber[k]] = node_class[k];
      m_held[renumber[k]] = held[k];
    }
  m.tri.resize(3, static_cast<Eigen::Index>(triangles.size()));
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) m.tri(k, f) = renumber[triangles[f][k]];
  m.tri_entity = triangle_surface;
  std::vector<std::array<int, 2>> lines;
  for (const auto& [tag, on] : boundary.curve_seeds)
    for (std::size_t k = 0; k + 1 < on.size(); ++k) {
      lines.push_back({renumber[on[k]], renumber[on[k + 1]]});
      m.line_entity.push_back(tag);
    }
  m.line.resize(2, static_cast<Eigen::Index>(lines.size()));
  for (std::size_t k = 0; k < lines.size(); ++k) m.line.col(k) << lines[k][0], lines[k][1];
  for (std::size_t k = 0; k < boundary.classes.size(); ++k)
    if (boundary.classes[k].dim == 0) {
      m.point_node.push_back(renumber[k]);
      m.point_entity.push_back(boundary.classes[k].tag);
    }
  // Edge flips that raise the worst mean ratio in the metric (at each
  // triangle's centroid; Q11 and Gmsh's ICN for a linear triangle), after
  // the smoothing: the radius ratio's flips lowered the worst mean ratio.
  const auto metric_mean_ratio = [&metric](const Eigen::Matrix<double, 2, 3>& X) {
    const Eigen::Matrix2d M = metric.metric_at(X.rowwise().mean());
    const Eigen::Vector2d a = X.col(1) - X.col(0), b = X.col(2) - X.col(0), c = b - a;
    const double area = 0.5 * std::sqrt(M.determinant()) * (a.x() * b.y() - a.y() * b.x());
    return 4 * std::sqrt(3.0) * area / (a.dot(M * a) + b.dot(M * b) + c.dot(M * c));
  };
  if (o.smooth > 0) {
    std::vector<char> free_node = movable_nodes(m, m_held);
    rep.smoothing_moves = smooth_free_nodes(m.x, m.tri, free_node, metric, o.smooth);
    if (o.cleanup) {
      rep.flips += flip_edges(m, metric_mean_ratio);
      // Valence-4 nodes whose quad is better without them go, on the
      // smoothed positions; the rest smoothed again round the new quads.
      const std::vector<int> gone = remove_valence_four(m, free_node, metric_mean_ratio);
      rep.valence_four = static_cast<int>(gone.size());
      if (!gone.empty()) {
        drop_nodes(m, gone, m_held);
        free_node = movable_nodes(m, m_held);
        rep.smoothing_moves += smooth_free_nodes(m.x, m.tri, free_node, metric, o.smooth);
        rep.flips += flip_edges(m, metric_mean_ratio);
      }
    }
    // Edges flipped towards valence 6 (valence_flips.h), on the smoothed
    // positions, the rest smoothed and flipped again round them.
    if (o.cleanup) {
      rep.valence_flips = flip_to_regular_valence(m, free_node, metric_mean_ratio, kValenceFloor);
      if (rep.valence_flips > 0) {
        rep.smoothing_moves += smooth_free_nodes(m.x, m.tri, free_node, metric, o.smooth);
        rep.flips += flip_edges(m, metric_mean_ratio);
      }
    }
    if (o.raise_worst > 0)
      rep.raise_steps = raise_worst_triangle(m.x, m.tri, free_node, metric, o.raise_worst);
  } else if (o.cleanup) {
    rep.flips = flip_edges(m, metric_mean_ratio);
  }
  // The shapes in the metric (Q11, the mean ratio, in M at each centroid).
  double sum = 0;
  rep.metric_quality_min = m.num_triangles() > 0 ? 1.0 : 0.0;
  for (int t = 0; t < m.num_triangles(); ++t) {
    Eigen::Matrix<double, 2, 3> X;
    for (int k = 0; k < 3; ++k) X.col(k) = m.x.col(m.tri(k, t));
    const double q = metric_mean_ratio(X);
    rep.metric_quality_min = std::min(rep.metric_quality_min, q);
    sum += q;
  }
  rep.metric_quality_mean = m.num_triangles() > 0 ? sum / m.num_triangles() : 0.0;
  return m;
}

}  // namespace homesh
