#include "pipeline/stages/voronoi_stage.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "core/check_mesh.h"
#include "core/error.h"
#include "core/progress.h"
#include "gmsh/boundary_sampling.h"
#include "gmsh/gmsh_call.h"
#include "gmsh/metric_view.h"
#include "pipeline/stage_registry.h"
#include "voronoi/boundary_encroachment.h"
#include "voronoi/conforming_dual.h"
#include "voronoi/curve_division.h"
#include "voronoi/lloyd_relaxation.h"
#include "voronoi/loop_distance.h"
#include "voronoi/metric_seeding.h"
#include "voronoi/metric_smoothing.h"
#include "voronoi/refine_dual.h"
#include "voronoi/size_metric.h"
#include "voronoi/voronoi_engines.h"
#include "voronoi/voronoi_files.h"
#include "voronoi/window_regrowth.h"

namespace homesh {
namespace {

using gmsh_adapter::SeededBoundary;
using Clock = std::chrono::steady_clock;

constexpr int kCurveSamples = 2000;    // fine samples per boundary curve
constexpr double kCellsPerSize = 6.0;  // automatic grid: smallest size over this many cells
constexpr int kGridMin = 200, kGridMax = 1500;
constexpr int kCoarseMax = 400;      // coarse metric grid nodes along the longer side, at most
constexpr double kBandCells = 8.0;   // the domain's distance is exact this many cells out
constexpr int kLloydCoarsening = 2;  // Lloyd's iteration on a grid this many times coarser

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// One surface's boundary: the seed loops (domain on the left) and the finely
// sampled polygons.
struct SurfaceLoops {
  std::vector<std::array<int, 2>> segments;  // boundary seed pairs
  std::vector<Eigen::Matrix2Xd> polygons;
  Eigen::Vector2d lo, hi;
};

SurfaceLoops surface_loops(const SeededBoundary& b, const gmsh_adapter::SurfaceBoundary& s) {
  SurfaceLoops out;
  std::vector<std::vector<std::array<int, 2>>> loop_segments;
  for (const auto& loop : s.loops) {
    std::vector<int> seeds;
    std::vector<Eigen::Vector2d> pts;
    for (const gmsh_adapter::LoopCurve& c : loop) {
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
    const bool flip = (area > 0) == (depth % 2 == 1);
    for (auto [a, c] : loop_segments[l])
      out.segments.push_back(flip ? std::array<int, 2>{c, a} : std::array<int, 2>{a, c});
  }
  out.lo = out.polygons.front().rowwise().minCoeff();
  out.hi = out.polygons.front().rowwise().maxCoeff();
  for (const auto& p : out.polygons) {
    out.lo = out.lo.cwiseMin(p.rowwise().minCoeff());
    out.hi = out.hi.cwiseMax(p.rowwise().maxCoeff());
  }
  return out;
}

// The grid over [lo, hi] plus `margin` cells, `n` nodes along the longer side.
CartesianGrid grid_over(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, int n, int margin) {
  const double ds = (hi - lo).maxCoeff() / (n - 1 - 2 * margin);
  const Eigen::Vector2d pad = Eigen::Vector2d::Constant(margin * ds);
  const int nx = static_cast<int>(std::ceil((hi.x() - lo.x()) / ds)) + 1 + 2 * margin;
  const int ny = static_cast<int>(std::ceil((hi.y() - lo.y()) / ds)) + 1 + 2 * margin;
  CartesianGrid g;
  g.origin = lo - pad;
  g.dx = g.dy = ds;
  g.nx = nx;
  g.ny = ny;
  return g;
}

// The metric field of option `metric`: iso (sizes of Gmsh's default mesh,
// `reference`), bl (that, fine across the walls), a Gmsh tensor view (probed
// on the coarse grid of iso) or a file.
MetricField make_metric(const std::string& metric, const Mesh& reference, const Eigen::Vector2d& lo,
                        const Eigen::Vector2d& hi, const SeededBoundary* walls_from,
                        const std::vector<int>& walls) {
  const bool view = gmsh_adapter::names_metric_view(metric);
  if (metric != "iso" && metric != "bl" && !view) return read_metric_file(metric);
  const Eigen::MatrixXi tri = reference.tri.topRows(3);
  const Eigen::VectorXd h = mean_edge_length(reference.x, tri);
  const double h_min = (h.array() > 0).select(h.array(), h.maxCoeff()).minCoeff();
  const int n = std::clamp(static_cast<int>(std::ceil((hi - lo).maxCoeff() / (0.5 * h_min))) + 1,
                           16, kCoarseMax);
  const CartesianGrid coarse = grid_over(lo, hi, n, 1);
  if (view) return gmsh_adapter::metric_from_view(gmsh_adapter::metric_view_tag(metric), coarse);
  const MetricField iso = iso_metric_from_sizes(coarse, reference.x, h, tri);
  if (metric == "iso") return iso;
  std::vector<Eigen::Matrix2Xd> polylines;
  for (const int c : walls) polylines.push_back(walls_from->curve_samples.at(c));
  return boundary_layer_metric(iso, polylines);
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
    const std::string at = path + ":" + std::to_string(list.lines[k]) + ": seed (" +
                           fmt::format("{}, {}", p.x(), p.y()) + ")";
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

void run(Context& ctx, const VoronoiStageOptions& o) {
  ctx.require_cad("voronoi");
  const std::string& metric_name = o.metric;
  const std::string& seeds_name = o.seeds;
  const std::string& engine = o.engine;
  const int grid_option = o.grid;
  const int lloyd = o.lloyd.iterations;
  const int smooth = o.smooth;
  const auto start = Clock::now();

  // Gmsh's default mesh: the sizes of the iso metric, and the model's
  // entities and physical groups.
  const Stage& mesher = stage("mesh");
  mesher.run(ctx, mesher.parse({}));
  const Mesh reference = *ctx.mesh;

  SeededBoundary boundary;
  MetricField metric = MetricField::constant(Eigen::Matrix2d::Identity());
  std::string walls_note;
  gmsh_adapter::gmsh_call("stage 'voronoi' on " + ctx.input, [&] {
    // Curves sampled once with a constant metric to find the box; the real
    // division follows once the metric is known.
    SeededBoundary shape = gmsh_adapter::seed_boundary(
        kCurveSamples, [](const Eigen::VectorXd& u, const Eigen::Matrix2Xd&, bool) {
          return std::vector<double>{u(0), u(u.size() - 1)};
        });
    Eigen::Vector2d lo = shape.curve_samples.begin()->second.col(0), hi = lo;
    for (const auto& [tag, x] : shape.curve_samples) {
      lo = lo.cwiseMin(x.rowwise().minCoeff());
      hi = hi.cwiseMax(x.rowwise().maxCoeff());
    }
    std::vector<int> walls;
    if (metric_name == "bl") {
      const std::vector<int> far = gmsh_adapter::curves_in_group("farfield");
      for (const auto& [tag, x] : shape.curve_samples)
        if (!std::binary_search(far.begin(), far.end(), tag)) walls.push_back(tag);
      walls_note = fmt::format(", walls: {} curves not in a group 'farfield'", walls.size());
    }
    metric = make_metric(metric_name, reference, lo, hi, &shape, walls);
    boundary = gmsh_adapter::seed_boundary(
        kCurveSamples, [&](const Eigen::VectorXd& u, const Eigen::Matrix2Xd& x, bool closed) {
          return divide_by_metric_length(u, x, metric, closed ? 3 : 1);
        });
  });
  const SeedList list = seeds_name == "auto" ? SeedList{} : read_seed_file(seeds_name);
  std::vector<char> list_used(list.points.cols(), 0);

  // One Voronoi problem per surface; the boundary seeds are shared.
  Mesh m;
  m.order = 1;
  std::vector<Eigen::Vector2d> nodes;
  for (Eigen::Index k = 0; k < boundary.seeds.cols(); ++k) nodes.push_back(boundary.seeds.col(k));
  m.node_class = boundary.classes;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> triangle_surface;
  const double h_min = metric.min_speed();
  int dual_triangles = 0, filled_triangles = 0, refined_seeds = 0;
  for (const gmsh_adapter::SurfaceBoundary& surface : boundary.surfaces) {
    const SurfaceLoops loops = surface_loops(boundary, surface);
    const double extent = (loops.hi - loops.lo).maxCoeff();
    const int n = grid_option > 0
                      ? grid_option
                      : std::clamp(static_cast<int>(std::ceil(extent / (h_min / kCellsPerSize))),
                                   kGridMin, kGridMax);
    VoronoiProblem p;
    p.grid = grid_over(loops.lo, loops.hi, n, 3);
    p.metric = metric;
    p.domain = loop_signed_distance(p.grid, loops.polygons, kBandCells * p.grid.ds());
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
    const auto seeding = Clock::now();
    // Automatic seeds: the front rows advancing from the boundary segments,
    // then Poisson-disc seeds spaced from both where the fronts meet.
    const bool auto_seeds = seeds_name == "auto";
    const SeedingOptions& so = o.seeding;
    const FrontSeeds front =
        auto_seeds ? metric_front_seeds(p.grid, p.domain, metric, bseeds, segments, so)
                   : FrontSeeds{};
    const Eigen::Matrix2Xd& front_seeds = front.seeds;
    Eigen::Matrix2Xd held(2, bseeds.cols() + front_seeds.cols());
    held << bseeds, front_seeds;
    // Lloyd's iteration holds the first row (and the corner seeds) and
    // relaxes the others where the fronts meet; rows are its fixed points
    // elsewhere, but the collisions need it.
    const Eigen::Index hold = bseeds.cols() + front.first_row;
    const Eigen::Matrix2Xd interior =
        auto_seeds ? metric_interior_seeds(p.grid, p.domain, metric, held)
                   : file_seeds(seeds_name, list, loops, p.grid, p.domain, bseeds, list_used);
    p.seeds.resize(2, held.cols() + interior.cols());
    p.seeds << held, interior;
    Progress phase("phase", 3);
    if (seeds_name == "auto" && lloyd > 0) {
      phase.update(0, "Lloyd's iteration on the seeds");
      // On a grid kLloydCoarsening times coarser: a centroid needs far fewer
      // cells per region than a dual triangle does.
      VoronoiProblem coarse = p;
      coarse.grid = grid_over(loops.lo, loops.hi, std::max(kGridMin, n / kLloydCoarsening), 3);
      coarse.domain =
          loop_signed_distance(coarse.grid, loops.polygons, kBandCells * coarse.grid.ds());
      p.seeds = lloyd_relaxation(coarse, static_cast<int>(hold), engine, o.lloyd);
    }
    // Automatic seeds inside a boundary segment's diametral circle go: that
    // segment could be in no dual.
    std::vector<int> encroaching;
    if (auto_seeds) {
      encroaching = encroaching_seeds(p.seeds, static_cast<int>(bseeds.cols()), segments);
      std::vector<int> keep;
      for (int k = 0, e = 0; k < p.seeds.cols(); ++k)
        if (e < static_cast<int>(encroaching.size()) && encroaching[e] == k)
          ++e;
        else
          keep.push_back(k);
      p.seeds = Eigen::Matrix2Xd(p.seeds(Eigen::all, keep));
    }
    const auto front_count = static_cast<Eigen::Index>(
        front_seeds.cols() - std::count_if(encroaching.begin(), encroaching.end(),
                                           [&](int k) { return k < held.cols(); }));
    const Eigen::Index interior_count = p.seeds.cols() - bseeds.cols() - front_count;
    const double seeding_time = seconds_since(seeding);

    phase.update(1, "growing " + std::to_string(p.seeds.cols()) + " crystals");
    const auto growth = Clock::now();
    RefineOptions refine;
    refine.segments = segments;
    const RefinedDual r = refine_dual(p, engine, {}, refine);
    const double growth_time = seconds_since(growth);
    // Where the dual misses the boundary, a finer grid round the spot.
    p.seeds = r.seeds;
    phase.update(2, "regrowing where the dual missed the boundary");
    const RegrownDual w = regrow_windows(
        p, r.result.dual.triangles, r.result.dual.vertices, segments,
        [&](const CartesianGrid& g) {
          return loop_signed_distance(g, loops.polygons, kBandCells * g.ds());
        },
        engine);
    const ConformingTriangulation c = conforming_triangulation(w.seeds, segments, w.triangles);

    int added = 0;
    for (const int a : r.added) added += a;
    ctx.log.info(
        "voronoi: surface {}: grid {} x {} (ds {:.4g}), {} boundary + {} front + {} interior "
        "seeds ({}, {:.2f} s), engine {} {:.2f} s",
        surface.tag, p.grid.nx, p.grid.ny, p.grid.ds(), bseeds.cols(), front_count, interior_count,
        seeds_name != "auto"
            ? seeds_name
            : fmt::format("Poisson-disc in the metric, {} Lloyd iterations, {} encroaching "
                          "on a boundary segment dropped",
                          lloyd, encroaching.size()),
        seeding_time, engine, growth_time);
    ctx.log.info(
        "voronoi: surface {}: dual {} triangles, check {} after {} refinement rounds (+{} "
        "seeds at faulty triple points)",
        surface.tag, r.result.dual.triangles.size(), r.ok() ? "passed" : "FAILED", r.added.size(),
        added);
    if (w.windows > 0)
      ctx.log.info(
          "voronoi: surface {}: the dual missed {} boundary segments: regrown in {} windows "
          "(finer grids of up to {} nodes per side, {} grown again twice as fine), +{} seeds",
          surface.tag, missed_segments(segments, r.result.dual.triangles).size(), w.windows,
          w.window_nodes, w.finer_windows, w.seeds.cols() - r.seeds.cols());
    if (c.filled > 0 || c.dual_dropped > 0)
      ctx.log.info(
          "voronoi: surface {}: the dual does not conform: {} of {} boundary segments missing "
          "from it, {} dual triangles dropped; constrained Delaunay (CGAL) of the same seeds "
          "filled {} triangles",
          surface.tag, c.boundary_missed, segments.size(), c.dual_dropped, c.filled);
    ctx.log.info("voronoi: surface {}: {} triangles, {} from the dual, {} from the fill",
                 surface.tag, c.triangles.size(), c.from_dual, c.filled);
    dual_triangles += c.from_dual;
    filled_triangles += c.filled;
    refined_seeds += added;

    // Interior and added seeds become nodes of the surface.
    std::vector<int> to_node(local_to_node);
    for (Eigen::Index k = bseeds.cols(); k < w.seeds.cols(); ++k) {
      to_node.push_back(static_cast<int>(nodes.size()));
      nodes.push_back(w.seeds.col(k));
      m.node_class.push_back({2, surface.tag, std::numeric_limits<double>::quiet_NaN()});
    }
    for (const auto& t : c.triangles) {
      triangles.push_back({to_node[t[0]], to_node[t[1]], to_node[t[2]]});
      triangle_surface.push_back(surface.tag);
    }
  }
  ctx.results["dual_triangles"] = dual_triangles;
  ctx.results["filled_triangles"] = filled_triangles;
  ctx.results["refined_seeds"] = refined_seeds;
  for (Eigen::Index k = 0; k < list.points.cols(); ++k)
    if (!list_used[k])
      throw Error(seeds_name + ":" + std::to_string(list.lines[k]) + ": seed (" +
                  fmt::format("{}, {}", list.points(0, k), list.points(1, k)) +
                  ") lies outside the domain");

  // Nodes no triangle uses (interior seeds cut off by a boundary chord) go.
  std::vector<int> renumber(nodes.size(), -1);
  for (const auto& t : triangles)
    for (const int v : t) renumber[v] = 0;
  for (std::size_t k = 0; k < boundary.classes.size(); ++k) renumber[k] = 0;
  int count = 0, dropped = 0;
  for (int& r : renumber) r = r < 0 ? (++dropped, -1) : count++;
  m.x.resize(2, count);
  std::vector<NodeClass> classes(count);
  for (std::size_t k = 0; k < nodes.size(); ++k)
    if (renumber[k] >= 0) {
      m.x.col(renumber[k]) = nodes[k];
      classes[renumber[k]] = m.node_class[k];
    }
  m.node_class = classes;
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
  m.entities = reference.entities;
  m.physicals = reference.physicals;
  if (smooth > 0) {
    std::vector<char> free_node(m.node_class.size());
    for (std::size_t k = 0; k < free_node.size(); ++k) free_node[k] = m.node_class[k].dim == 2;
    const int moves = smooth_free_nodes(m.x, m.tri, free_node, metric, smooth);
    ctx.log.info("voronoi: {} smoothing sweeps of the interior nodes, {} moves", smooth, moves);
  }
  check_mesh(m, "stage 'voronoi'");
  ctx.mesh = m;
  ctx.fields.clear();
  if (dropped > 0)
    ctx.log.info("voronoi: {} interior seeds outside the boundary polygon left out", dropped);
  ctx.log.info("voronoi: metric {}{}: {} nodes, {} triangles, {} boundary lines ({:.2f} s)",
               metric_name == "iso" ? "iso (sizes of Gmsh's default mesh)" : metric_name,
               walls_note, m.num_nodes(), m.num_triangles(), m.num_lines(), seconds_since(start));
}

}  // namespace

Stage voronoi_stage() {
  // Defaults: those of VoronoiStageOptions, SeedingOptions (voronoi/metric_seeding.h)
  // and LloydOptions (voronoi/lloyd_relaxation.h).
  using O = VoronoiStageOptions;
  std::vector<std::string> engines;
  for (const VoronoiEngine& e : voronoi_engines()) engines.push_back(e.name);
  OptionTable<O> t;
  t.add("metric", &O::metric, text(),
        "iso (the sizes of the mesh stage's default mesh) | bl (iso, 5 times finer across "
        "the walls: curves not in a group 'farfield') | viewN (the tensor view of tag N, "
        "e.g. merged by the .geo) | FILE.pos or FILE.msh (its last view, a tensor field) "
        "| FILE (a coarse grid of 2x2 SPD tensors, format in src/voronoi/voronoi_files.h)");
  t.add("seeds", &O::seeds, text(),
        "auto (front rows, then Poisson-disc in the metric) | FILE (interior seeds, one 'x y' "
        "per line; the boundary seeds are placed from the metric)");
  t.add(
      "front", [](O& o) -> int& { return o.seeding.front_rows; },
      integer(0, 1000, {{"all", kAllFrontRows}}),
      "with auto seeds: rows of seeds advancing from the boundary, each at the apexes of "
      "the unit triangles (in the metric) on the row before (Rebay's frontal placement), "
      "and a seed splitting each corner of 75-140 degrees; Poisson-disc seeds fill where "
      "the fronts meet, Lloyd's iteration holds the first row | N: N rows | 0: none, "
      "Poisson-disc seeds only");
  t.add(
      "lloyd", [](O& o) -> int& { return o.lloyd.iterations; }, integer(0, 100),
      "Lloyd iterations on the auto seeds: each interior seed but the first front row "
      "moves to the metric centroid of its region (0: none)");
  t.add("smooth", &O::smooth, integer(0, 100),
        "sweeps of smart smoothing of the interior nodes after the dual (Laplacian or "
        "ideal-apex position, then compass searches: on the worst triangle where it stays "
        "below 0.8, on the sum of inverse mean ratios; a move is kept only if the worst "
        "triangle round the node gets no worse in the metric; the connectivity stays the "
        "dual's; 0: none)");
  t.add("engine", &O::engine, one_of(engines), names_text(engines));
  t.add("grid", &O::grid,
        where<int>(
            integer(0, 20000), [](const int& n) { return n == 0 || n >= 32; },
            "must be 0 (automatic) or at least 32"),
        "grid nodes along the longer side (0: the smallest size over 6 cells, 200 to 1500)");
  return make_stage<O>("voronoi",
                       "new linear triangle mesh of the input's CAD, dual to the crystal Voronoi "
                       "diagram (thesis Ch 2; replaces any mesh)",
                       t, run, true);
}

}  // namespace homesh
