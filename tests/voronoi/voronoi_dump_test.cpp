// Hidden test cases that write data for scripts/voronoi_pictures.py and
// scripts/bench/voronoi_bench.py (run with the tag, never by default):
//
//   test_numeric "[.voronoi_pictures]"   the thesis examples, as CSV files
//   test_numeric "[.voronoi_bench]"      engine and CGAL timings, one CSV
//   test_numeric "[.voronoi_bench_general]"  fast marching with a domain or a
//                                        varying metric, one CSV
//
// Both write into the directory named by HOMESH_VORONOI_OUT (default: the
// working directory). The benchmark reads HOMESH_VORONOI_BENCH_GRID (grid
// nodes per side, default 2000), HOMESH_VORONOI_BENCH_SEEDS (comma-separated
// seed counts, default 10,100,1000,10000,100000) and
// HOMESH_VORONOI_BENCH_LEVEL_SET_MAX (largest seed count for the level-set
// engine, default 10000). Times are the process's CPU seconds (std::clock;
// the engines and CGAL run on one thread), which a machine shared with other
// jobs does not inflate as it does wall time.
#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "thesis_examples.h"
#include "voronoi/dual/cgal_delaunay.h"
#include "voronoi/dual/refine_dual.h"
#include "voronoi/dual/voronoi_delaunay.h"
#include "voronoi/engines/voronoi_engines.h"
#include "voronoi_test_support.h"

using namespace homesh;

namespace {

std::string env(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? v : fallback;
}

std::string out_path(const std::string& file) {
  return env("HOMESH_VORONOI_OUT", ".") + "/" + file;
}

// NAME_grid.csv (x0,y0,dx,dy,nx,ny), NAME_labels.csv (ny rows of nx labels),
// NAME_seeds.csv (x,y), NAME_triangles.csv (a,b,c), NAME_metric.csv (the
// coarse metric: x,y,m11,m12,m22; per-seed metrics at the seeds),
// NAME_boundary.csv (loop,x,y), NAME_faults.csv (x,y: where the last dual
// still fails its check).
void dump(const test::ThesisExample& e, const std::string& engine) {
  const VoronoiProblem& p = e.problem;
  const auto start = std::chrono::steady_clock::now();
  // As the thesis grows them: no seeds added (the faults are drawn instead).
  RefineOptions no_rounds;
  no_rounds.max_rounds = 0;
  const RefinedDual r = refine_dual(p, engine, {}, no_rounds);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string name = e.name + "_" + engine;
  const CartesianGrid& g = p.grid;
  std::ofstream(out_path(name + "_grid.csv"))
      << "x0,y0,dx,dy,nx,ny,seconds,rounds,added,check_ok,isolated\n"
      << g.origin.x() << "," << g.origin.y() << "," << g.dx << "," << g.dy << "," << g.nx << ","
      << g.ny << "," << seconds << "," << r.added.size() << "," << r.seeds.cols() - p.seeds.cols()
      << "," << r.ok() << "," << r.result.regions.isolated.size() << "\n";
  std::ofstream labels(out_path(name + "_labels.csv"));
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      labels << r.result.partition.labels(g.index(i, j)) << (i + 1 < g.nx ? "," : "\n");
  std::ofstream seeds(out_path(name + "_seeds.csv"));
  seeds << "x,y\n";
  for (int s = 0; s < r.seeds.cols(); ++s) seeds << r.seeds(0, s) << "," << r.seeds(1, s) << "\n";
  std::ofstream tris(out_path(name + "_triangles.csv"));
  tris << "a,b,c\n";
  for (const auto& t : r.result.dual.triangles) tris << t[0] << "," << t[1] << "," << t[2] << "\n";
  std::ofstream metric(out_path(name + "_metric.csv"));
  metric << "x,y,m11,m12,m22\n";
  const auto row = [&](const Eigen::Vector2d& x, const Eigen::Matrix2d& M) {
    metric << x.x() << "," << x.y() << "," << M(0, 0) << "," << M(0, 1) << "," << M(1, 1) << "\n";
  };
  if (!p.seed_metrics.empty()) {
    for (int s = 0; s < p.seeds.cols(); ++s) row(p.seeds.col(s), p.seed_metrics[s]);
  } else {
    const CartesianGrid& c = p.metric.coarse();
    const bool constant = c.node_count() == 4;
    for (int j = 0; j < (constant ? 5 : c.ny); ++j)
      for (int i = 0; i < (constant ? 5 : c.nx); ++i) {
        const Eigen::Vector2d x =
            constant
                ? Eigen::Vector2d(g.origin + Eigen::Vector2d((i + 0.5) * (g.nx - 1) * g.dx / 5,
                                                             (j + 0.5) * (g.ny - 1) * g.dy / 5))
                : c.point(i, j);
        row(x, constant ? p.metric.metric(0) : p.metric.metric(c.index(i, j)));
      }
  }
  std::ofstream faults(out_path(name + "_faults.csv"));
  faults << "x,y\n";
  const Eigen::Matrix2Xd f = dual_faults(r.seeds, r.result);
  for (int k = 0; k < f.cols(); ++k) faults << f(0, k) << "," << f(1, k) << "\n";
  std::ofstream bnd(out_path(name + "_boundary.csv"));
  bnd << "loop,x,y\n";
  for (std::size_t l = 0; l < e.boundary.size(); ++l)
    for (int k = 0; k < e.boundary[l].cols(); ++k)
      bnd << l << "," << e.boundary[l](0, k) << "," << e.boundary[l](1, k) << "\n";
}

}  // namespace

TEST_CASE("dump the thesis examples for the pictures", "[.voronoi_pictures]") {
  for (const std::string engine : {"fast_marching", "level_set"}) {
    for (int kind = 0; kind < 3; ++kind) dump(test::five_seeds(kind, 301), engine);
    dump(test::labelle_shewchuk(false, 301), engine);
    dump(test::labelle_shewchuk(true, 301), engine);
  }
  dump(test::non_convex_17(401), "fast_marching");
  dump(test::aerofoil_130(false, 600), "fast_marching");
  dump(test::aerofoil_130(true, 600), "fast_marching");
  SUCCEED();
}

TEST_CASE("benchmark the engines against CGAL", "[.voronoi_bench]") {
  const int n = std::stoi(env("HOMESH_VORONOI_BENCH_GRID", "2000"));
  const int level_set_max = std::stoi(env("HOMESH_VORONOI_BENCH_LEVEL_SET_MAX", "10000"));
  std::stringstream list(env("HOMESH_VORONOI_BENCH_SEEDS", "10,100,1000,10000,100000"));
  std::ofstream csv(out_path("voronoi_bench.csv"));
  csv << "seeds,method,grid,seconds,steps,triangles,cgal_in_square,matching\n";
  for (std::string item; std::getline(list, item, ',');) {
    const int S = std::stoi(item);
    VoronoiProblem p;
    p.grid = CartesianGrid::spanning({0, 0}, {1, 1}, n, n);
    p.seeds = test::uniform_seeds(S, 1, 0.0, 1.0);
    std::clock_t start = std::clock();
    const auto cgal = cgal_delaunay_triangles(p.seeds);
    const auto since = [&] { return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC; };
    const double cgal_seconds = since();
    // The triangles a partition of the square can show: circumcentre inside.
    std::set<std::array<int, 3>> reference;
    for (const auto& t : cgal) {
      const Eigen::Vector2d c =
          test::circumcentre(p.seeds.col(t[0]), p.seeds.col(t[1]), p.seeds.col(t[2]));
      if (test::inside_box(c, 0.0, 1.0) > 0.0) reference.insert(t);
    }
    csv << S << ",cgal," << n << "," << cgal_seconds << ",0," << cgal.size() << ","
        << reference.size() << "," << reference.size() << "\n";
    for (const std::string engine : {"fast_marching", "level_set"}) {
      if (engine == "level_set" && S > level_set_max) continue;
      start = std::clock();
      const CrystalPartition part = grow_crystals(p, engine);
      const double seconds = since();
      const RegionReport regions = analyse_regions(p.grid, part.labels, p.seeds, p.domain);
      const DualTriangulation dual = dual_triangulation(
          p.grid, part.labels, p.seeds, part.collisions, regions.adjacent, p.metric);
      int matching = 0;
      for (const auto& t : test::rotated(dual.triangles)) matching += reference.count(t) > 0;
      csv << S << "," << engine << "," << n << "," << seconds << "," << part.steps << ","
          << dual.triangles.size() << "," << reference.size() << "," << matching << std::endl;
    }
  }
  SUCCEED();
}

// Fast marching where each update does the full work (Hopf-Lax, sources,
// visibility): the thesis' aerofoil (a domain; isotropic, or an anisotropic
// metric field) and the benchmark's square with 1000 seeds under a metric
// field that turns (no domain) or round a hole (a domain, constant metric).
// Best of three CPU times of grow_crystals; rate = grid nodes over seconds.
// HOMESH_VORONOI_BENCH_CASE names one case to run alone.
TEST_CASE("benchmark fast marching on the general path", "[.voronoi_bench_general]") {
  const int n = std::stoi(env("HOMESH_VORONOI_BENCH_GRID", "2000"));
  std::vector<std::pair<std::string, VoronoiProblem>> cases;
  cases.emplace_back("aerofoil_iso_600", test::aerofoil_130(false, 600).problem);
  cases.emplace_back("aerofoil_aniso_600", test::aerofoil_130(true, 600).problem);
  VoronoiProblem square;
  square.grid = CartesianGrid::spanning({0, 0}, {1, 1}, n, n);
  square.seeds = test::uniform_seeds(1000, 1, 0.0, 1.0);
  const CartesianGrid coarse = CartesianGrid::spanning({0, 0}, {1, 1}, 21, 21);
  std::vector<Eigen::Matrix2d> M;
  for (int j = 0; j < coarse.ny; ++j)
    for (int i = 0; i < coarse.nx; ++i)
      M.push_back(metric_from_axes(M_PI * (i + j) / 20.0, 0.03, 0.01));
  VoronoiProblem turning = square;
  turning.metric = MetricField(coarse, M);
  cases.emplace_back("square_turning_metric", turning);
  VoronoiProblem holed = square;
  holed.domain = test::square_with_hole(holed.grid, 64);
  Eigen::Matrix2Xd kept(2, 0);
  for (int s = 0; s < square.seeds.cols(); ++s)
    if ((square.seeds.col(s) - Eigen::Vector2d(0.5, 0.5)).norm() > 0.21) {
      kept.conservativeResize(2, kept.cols() + 1);
      kept.col(kept.cols() - 1) = square.seeds.col(s);
    }
  holed.seeds = kept;
  cases.emplace_back("square_hole", holed);
  std::ofstream csv(out_path("voronoi_bench_general.csv"));
  csv << "case,seeds,nodes,seconds,steps,mnodes_per_s\n";
  const std::string only = env("HOMESH_VORONOI_BENCH_CASE", "");
  for (const auto& [name, p] : cases) {
    if (!only.empty() && name != only) continue;
    double best = 1e300;
    long steps = 0;
    for (int run = 0; run < 3; ++run) {
      const std::clock_t start = std::clock();
      const CrystalPartition part = grow_crystals(p, "fast_marching");
      best = std::min(best, static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC);
      steps = part.steps;
    }
    const int nodes = p.grid.node_count();
    csv << name << "," << p.seeds.cols() << "," << nodes << "," << best << "," << steps << ","
        << nodes / best / 1e6 << std::endl;
  }
  SUCCEED();
}
