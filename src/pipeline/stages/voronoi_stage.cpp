#include "pipeline/stages/voronoi_stage.h"

#include <fmt/core.h>
#include <gmsh.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/check_mesh.h"
#include "gmsh/boundary_sampling.h"
#include "gmsh/gmsh_call.h"
#include "gmsh/metric_view.h"
#include "gmsh/option_scope.h"
#include "pipeline/stages/mesh_stage.h"
#include "voronoi/engines/voronoi_engines.h"
#include "voronoi/metric/size_metric.h"
#include "voronoi/seeding/curve_division.h"
#include "voronoi/voronoi_files.h"
#include "voronoi/voronoi_mesh.h"

namespace homesh {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kCurveSamples = 2000;  // fine samples per boundary curve
constexpr int kCoarseMax = 400;      // coarse metric grid nodes along the longer side, at most
// The iso metric's sizes come from Gmsh's mesh at this many times the sizes
// asked for, its edge lengths divided by it: Gmsh multiplies every size (of
// the points, the curvature, the fields, after Mesh.MeshSizeMin/Max) by
// Mesh.MeshSizeFactor last (BGM_MeshSize in its BackgroundMeshTools.cpp), so
// the coarser mesh has the same size field, at a quarter of the triangles
// and of Gmsh's time. On the plate with a hole at 3e4 triangles that mesh
// was 0.85 s of the stage's 2.4 s (docs/voronoi.md). Where it has fewer than
// kReferenceMinTriangles the shapes bound its edges more than the sizes do
// (the plate at factor 2, 4 here: 44 triangles, whose edges made 1.7 times
// the triangles asked for), and the mesh at the sizes asked for is taken.
// So it is above kReferenceMaxTriangles (about 2e4 triangles asked for): the
// coarser sizes cost the mean shape 0.0007-0.002 there (plate at 3e4 and
// 1.2e5 triangles: 0.9889 and 0.9909 against 0.9896 and 0.9926, frontal's
// 0.9890 and 0.9912), and Gmsh's mesh is a smaller share of the time.
constexpr double kReferenceCoarsening = 2;
constexpr long kReferenceMinTriangles = 100, kReferenceMaxTriangles = 5000;

// The metric field of option `metric`: iso (sizes of Gmsh's default mesh,
// `reference`), bl (that, fine across the walls), a Gmsh tensor view (probed
// on the coarse grid of iso) or a file.
MetricField make_metric(const std::string& metric, const Mesh& reference, double coarsening,
                        const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                        const SeededBoundary* walls_from, const std::vector<int>& walls,
                        const BoundaryLayerOptions& layer) {
  const bool view = gmsh_adapter::names_metric_view(metric);
  if (metric != "iso" && metric != "bl" && !view) return read_metric_file(metric);
  const Eigen::MatrixXi tri = reference.tri.topRows(3);
  const Eigen::VectorXd h = mean_edge_length(reference.x, tri) / coarsening;
  const double h_min = (h.array() > 0).select(h.array(), h.maxCoeff()).minCoeff();
  const int n = std::clamp(static_cast<int>(std::ceil((hi - lo).maxCoeff() / (0.5 * h_min))) + 1,
                           16, kCoarseMax);
  const CartesianGrid coarse = CartesianGrid::covering(lo, hi, n, 1);
  if (view) return gmsh_adapter::metric_from_view(gmsh_adapter::metric_view_tag(metric), coarse);
  MetricField iso = iso_metric_from_sizes(coarse, reference.x, h, tri);
  if (metric == "iso") return iso;
  std::vector<Eigen::Matrix2Xd> polylines;
  for (const int c : walls) polylines.push_back(walls_from->curve_samples.at(c));
  return boundary_layer_metric(iso, polylines, layer);
}

// How the dual was made, for the log.
std::string dual_text(const VoronoiSurfaceReport& s, const VoronoiMeshOptions& o) {
  if (s.exact_dual && s.metric_dual)
    return "exact dual (Delaunay of the seeds in the metric, no growth)";
  if (s.exact_dual) return "exact dual (Delaunay of the seeds, no growth)";
  return "engine " + o.engine;
}

void log_report(Log& log, const VoronoiReport& rep, const VoronoiStageOptions& o) {
  for (const VoronoiSurfaceReport& s : rep.surfaces) {
    log.info(
        "voronoi: surface {}: grid {} x {} (ds {:.4g}), {} boundary + {} front + {} interior "
        "seeds ({}, {:.2f} s), {} {:.2f} s",
        s.tag, s.grid.nx, s.grid.ny, s.grid.ds(), s.boundary_seeds, s.front_seeds, s.interior_seeds,
        o.seeds != "auto"
            ? o.seeds
            : fmt::format("Poisson-disc in the metric, {}, {} encroaching on a "
                          "boundary segment dropped",
                          s.lloyd_iterations == 0
                              ? std::string("no Lloyd iterations")
                              : fmt::format("{} Lloyd iterations on {} cells", s.lloyd_iterations,
                                            s.exact_lloyd ? "exact" : "grown"),
                          s.encroaching_dropped),
        s.seeding_seconds, dual_text(s, o.mesher), s.growth_seconds);
    if (s.columns > 0)
      log.info(
          "voronoi: surface {}: {} seeds in {} columns across the anisotropic walls (up to {} a "
          "column)",
          s.tag, s.column_seeds, s.columns, s.column_rows);
    if (s.exact_dual && s.metric_dual)
      log.info(
          "voronoi: surface {}: constrained Delaunay of the seeds, {} edges flipped to make it "
          "Delaunay in the metric; {} triangles, {} with an edge left not Delaunay in it",
          s.tag, s.metric_flips, s.dual_size, s.filled);
    else if (s.exact_dual)
      log.info("voronoi: surface {}: dual {} triangles, {} boundary segments not among their edges",
               s.tag, s.dual_size, s.missed_segments);
    else
      log.info(
          "voronoi: surface {}: dual {} triangles, check {} after {} refinement rounds (+{} "
          "seeds at faulty triple points)",
          s.tag, s.dual_size, s.dual_checked ? "passed" : "FAILED", s.refinement_rounds,
          s.refined_seeds);
    if (s.windows > 0)
      log.info(
          "voronoi: surface {}: {} seeds finer than the grid grown in {} windows; then the dual "
          "missed {} boundary segments: regrown in {} windows (finer grids of up to {} nodes per "
          "side, {} grown again twice as fine), +{} seeds",
          s.tag, s.fine_seeds, s.fine_windows, s.missed_segments, s.windows - s.fine_windows,
          s.window_nodes, s.finer_windows, s.regrown_seeds);
    if (s.filled > 0 || s.dual_dropped > 0)
      log.info(
          "voronoi: surface {}: the dual does not conform: {} of {} boundary segments missing "
          "from it, {} dual triangles dropped; constrained Delaunay (CGAL) of the same seeds "
          "filled {} triangles",
          s.tag, s.boundary_missed, s.segments, s.dual_dropped, s.filled);
    log.info("voronoi: surface {}: {} triangles, {} from the dual, {} from the fill", s.tag,
             s.from_dual + s.filled, s.from_dual, s.filled);
  }
  if (o.mesher.cleanup)
    log.info(
        "voronoi: clean-up: {} interior nodes of three triangles removed, {} of four (where "
        "their quad is better without them), {} edges flipped, {} of them towards valence 6",
        rep.valence_three, rep.valence_four, rep.flips + rep.valence_flips, rep.valence_flips);
  if (o.mesher.smooth > 0)
    log.info(
        "voronoi: {} smoothing sweeps of the interior nodes, {} moves; {} steps raising the "
        "worst triangle",
        o.mesher.smooth, rep.smoothing_moves, rep.raise_steps);
  log.info(
      "voronoi: shape in the metric (mean ratio, Q11 at each centroid's metric): worst {:.4f}, "
      "mean {:.4f}",
      rep.metric_quality_min, rep.metric_quality_mean);
  if (rep.dropped_seeds > 0)
    log.info("voronoi: {} interior seeds outside the boundary polygon left out", rep.dropped_seeds);
}

// Adapts the model to voronoi_mesh: Gmsh's default mesh (for the iso metric's
// sizes, the entities and the physical groups), the metric, the seeded CAD
// boundary; then the mesh back with the model's entities.
void run(Context& ctx, const VoronoiStageOptions& o) {
  ctx.require_cad("voronoi");
  const auto start = Clock::now();
  MeshOptions sizes;
  // With metric=bl the full mesh: seeding the layer takes most of the time
  // there, and the coarser sizes moved the curved worst of the corpus's
  // layers by -0.09 to +0.03 (naca23015_a12_bl_1e-5 at p = 3: 0.836 against
  // 0.924; docs/voronoi.md).
  double factor = o.factor, coarsening = o.metric == "bl" ? 1 : kReferenceCoarsening;
  gmsh_adapter::OptionScope flexible;
  gmsh_adapter::gmsh_call("stage 'voronoi' on " + ctx.input, [&] {
    if (factor <= 0) gmsh::option::getNumber("Mesh.MeshSizeFactor", factor);
    // Transfinite curves take the factor too (their node counts divided by it).
    if (coarsening > 1) flexible.set("Mesh.FlexibleTransfinite", 1);
  });
  sizes.factor = coarsening * factor;
  Mesh reference = gmsh_mesh(ctx.input, sizes);
  if (coarsening > 1 && (reference.num_triangles() < kReferenceMinTriangles ||
                         reference.num_triangles() > kReferenceMaxTriangles)) {
    coarsening = 1;
    sizes.factor = factor;
    reference = gmsh_mesh(ctx.input, sizes);
  }

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
    if (o.metric == "bl") {
      const std::vector<int> far = gmsh_adapter::curves_in_group("farfield");
      for (const auto& [tag, x] : shape.curve_samples)
        if (!std::binary_search(far.begin(), far.end(), tag)) walls.push_back(tag);
      walls_note = fmt::format(", walls: {} curves not in a group 'farfield'", walls.size());
      if (far.empty())
        ctx.log.warn(
            "voronoi: {} has no curve in a physical group 'farfield': metric=bl refines "
            "across every boundary curve ({}) as a wall",
            ctx.input, walls.size());
    }
    metric = make_metric(o.metric, reference, coarsening, lo, hi, &shape, walls, o.layer);
    boundary = gmsh_adapter::seed_boundary(
        kCurveSamples, [&](const Eigen::VectorXd& u, const Eigen::Matrix2Xd& x, bool closed) {
          return divide_by_metric_length(u, x, metric, closed ? 3 : 1);
        });
  });
  VoronoiMeshOptions mesher = o.mesher;
  SeedList list;
  if (o.seeds != "auto") {
    list = read_seed_file(o.seeds);
    mesher.seed_list = &list;
    mesher.seed_path = o.seeds;
  }
  VoronoiReport rep;
  Mesh m = voronoi_mesh(boundary, metric, mesher, &rep);
  m.entities = reference.entities;
  m.physicals = reference.physicals;
  log_report(ctx.log, rep, o);
  check_mesh(m, "stage 'voronoi'");
  ctx.results["dual_triangles"] = rep.dual_triangles;
  ctx.results["filled_triangles"] = rep.filled_triangles;
  ctx.results["refined_seeds"] = rep.refined_seeds;
  long columns = 0;
  for (const VoronoiSurfaceReport& s : rep.surfaces) columns += s.column_seeds;
  ctx.results["column_seeds"] = static_cast<double>(columns);
  ctx.results["metric_quality_min"] = rep.metric_quality_min;
  ctx.results["metric_quality_mean"] = rep.metric_quality_mean;
  ctx.log.info("voronoi: metric {}{}: {} nodes, {} triangles, {} boundary lines ({:.2f} s)",
               o.metric == "iso" ? "iso (sizes of Gmsh's default mesh)" : o.metric, walls_note,
               m.num_nodes(), m.num_triangles(), m.num_lines(),
               std::chrono::duration<double>(Clock::now() - start).count());
  ctx.mesh = std::move(m);
  ctx.fields.clear();
}

}  // namespace

Stage voronoi_stage() {
  // Defaults: those of VoronoiStageOptions and of VoronoiMeshOptions (voronoi/voronoi_mesh.h).
  using O = VoronoiStageOptions;
  std::vector<std::string> engines;
  for (const VoronoiEngine& e : voronoi_engines()) engines.push_back(e.name);
  OptionTable<O> t;
  t.add("metric", &O::metric, text(),
        "iso (the sizes of the mesh stage's default mesh, which follows the .geo's size "
        "fields, its Background Field included) | bl (iso, bl_aspect times finer across "
        "the walls: curves not in a group 'farfield') | viewN (the tensor view of tag N, "
        "e.g. merged by the .geo) | FILE.pos or FILE.msh (its last view, a tensor field) "
        "| FILE (a coarse grid of 2x2 SPD tensors, format in src/voronoi/voronoi_files.h)");
  t.add(
      "bl_aspect", [](O& o) -> double& { return o.layer.wall_aspect; }, real(1, 1e4),
      "with metric=bl: the sizes' ratio along / across the walls at the walls");
  t.add(
      "bl_thickness", [](O& o) -> double& { return o.layer.thickness; }, real(0, 1e4, "(]"),
      "with metric=bl: the size across the walls reaches the iso size this many iso sizes "
      "from the walls (linearly)");
  t.add("factor", &O::factor, real(0),
        "factor on the sizes of Gmsh's default mesh, which the iso metric follows "
        "(Mesh.MeshSizeFactor; 0 = the model's, e.g. set by the .geo or the script)");
  t.add("seeds", &O::seeds, text(),
        "auto (front rows, then lattices and Poisson-disc in the metric, as `interior`) | "
        "FILE (interior seeds, one 'x y' per line; the boundary seeds are placed from the "
        "metric)");
  t.add(
      "front", [](O& o) -> int& { return o.mesher.seeding.front_rows; },
      integer(0, 1000, {{"all", kAllFrontRows}}),
      "with auto seeds: rows of seeds advancing from the boundary, each at the apexes of "
      "the unit triangles (in the metric) on the row before (Rebay's frontal placement), "
      "and a seed splitting each corner of 75-140 degrees; the `interior` seeds fill where "
      "the fronts meet, Lloyd's iteration holds the first row | N: N rows | 0: none, "
      "`interior` seeds only. Where the metric is at least 2:1 at a wall, columns come "
      "first: seeds on the wall's normals at unit steps of the metric up to where it is "
      "below 1.5:1, a fan of them at sharp convex corners, held by Lloyd and the clean-up");
  t.add(
      "interior", [](O& o) -> std::string& { return o.mesher.seeding.interior; },
      one_of({"lattice", "poisson"}),
      "with auto seeds, where the front rows leave off: lattice (hexagonal lattices of unit "
      "edges in the metric grown breadth first from the seeds before them, the direction "
      "carried from seed to seed as in Gmsh's packing of parallelograms, then Poisson-disc "
      "seeds in the gaps where they meet; where the metric is isotropic everywhere, "
      "Poisson-disc seeds elsewhere) | poisson (Poisson-disc seeds only)");
  t.add(
      "lloyd", [](O& o) -> int& { return o.mesher.lloyd.iterations; },
      integer(0, 100, {{"auto", kAutoIterations}}),
      "Lloyd iterations on the auto seeds (auto: 10 on exact cells and on grown ones): each "
      "interior seed but the first front row "
      "moves to the metric centroid of its region (0: none)");
  t.add(
      "lloyd_cells", [](O& o) -> std::string& { return o.mesher.lloyd.cells; },
      one_of({"auto", "exact", "grown"}),
      "the regions Lloyd's centroids are taken of | exact: the seeds' Euclidean Voronoi cells "
      "(CGAL), weighted by sqrt(det M) M, no grid | grown: the crystals grown on the grid | "
      "auto: exact with dual=exact or where the metric is isotropic everywhere, else grown");
  t.add(
      "dual", [](O& o) -> std::string& { return o.mesher.dual; }, one_of({"exact", "grown"}),
      "the triangulation of the seeds | exact: their Delaunay triangulation (CGAL), dual to "
      "their Euclidean Voronoi cells, no grid; where the metric is anisotropic, made Delaunay "
      "in it by edge flips (Lawson's, in the metric of each quad) | grown: dual to the "
      "crystals grown on the grid (thesis Ch 2)");
  t.add(
      "smooth", [](O& o) -> int& { return o.mesher.smooth; }, integer(0, 100),
      "sweeps of smart smoothing of the interior nodes after the dual (Laplacian or "
      "ideal-apex position, then compass searches: on the worst triangle where it stays "
      "below 0.8, on the sum of inverse mean ratios; a move is kept only if the worst "
      "triangle round the node gets no worse in the metric; the connectivity stays the "
      "dual's; 0: none)");
  t.add(
      "raise", [](O& o) -> int& { return o.mesher.raise_worst; }, integer(0, 100000),
      "after the smoothing and the flips, at most N steps on the mesh's worst triangle: each "
      "of its interior corners moves (compass search) to make the worst triangle round it "
      "the best, until the worst has no corner that can raise it (0: none)");
  t.add(
      "cleanup", [](O& o) -> bool& { return o.mesher.cleanup; }, boolean(),
      "topological clean-up of the dual: interior nodes of only three triangles removed (their "
      "triangles merged), edges flipped where the other diagonal raises the worst mean ratio "
      "in the metric (Q11), after the smoothing, interior nodes of four triangles removed "
      "where the better split of their quad raises the worst of the four, and edges flipped "
      "where that brings the valences nearer 6 with no triangle below 0.7 (Frey and Field's "
      "relaxation) | off: the dual's connectivity");
  t.add(
      "engine", [](O& o) -> std::string& { return o.mesher.engine; }, one_of(engines),
      names_text(engines));
  t.add(
      "grid", [](O& o) -> int& { return o.mesher.grid; },
      where<int>(
          integer(0, 20000), [](const int& n) { return n == 0 || n >= 32; },
          "must be 0 (automatic) or at least 32"),
      "grid nodes along the longer side (0: automatic: with the exact dual, where the grid "
      "serves only the seeds' inside tests, 2 cells per smallest size; with the grown one, "
      "see windows)");
  t.add(
      "windows", [](O& o) -> bool& { return o.mesher.fine_windows; }, boolean(),
      "with grid=0 and the grown dual: the crystals grow on a grid of 6 cells per size for "
      "half the seeds, 200 to "
      "1500 nodes along the longer side, and in windows round the finer seeds on grids of "
      "their own (Lloyd's iteration too) | off: on one grid of 6 cells per smallest size");
  return make_stage<O>("voronoi",
                       "new linear triangle mesh of the input's CAD, dual to the Voronoi diagram "
                       "of seeds placed in the metric (in columns across the walls where it is "
                       "anisotropic): their Delaunay triangulation in the metric, or with "
                       "dual=grown the dual of crystals grown in it (thesis Ch 2) (replaces any "
                       "mesh)",
                       t, run, true, true);
}

}  // namespace homesh
