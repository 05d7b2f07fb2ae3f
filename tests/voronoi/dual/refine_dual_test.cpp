#include "voronoi/dual/refine_dual.h"

#include <catch2/catch.hpp>

#include "../voronoi_test_support.h"

using namespace homesh;

namespace {
// 40 random seeds (set `set`) on a coarse 101 x 101 grid of the unit square, a
// constant anisotropic metric.
VoronoiProblem coarse_seed_set(unsigned set) {
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({0, 0}, {1, 1}, 101, 101);
  p.seeds = test::uniform_seeds(40, set, 0.02, 0.98);
  p.metric = MetricField::constant(metric_from_axes(0.3, 1.0, 0.25));
  return p;
}
}  // namespace

TEST_CASE("seeds added at the failing triple points repair the dual", "[voronoi][refine]") {
  // 40 random seeds on a coarse 101 x 101 grid: near-degenerate vertices
  // shorter than a cell break the dual of some sets; a seed at each faulty
  // Voronoi vertex repairs every one of them within the rounds allowed.
  int failing = 0;
  for (unsigned set = 1; set <= 12; ++set) {
    INFO("seed set " << set);
    const VoronoiProblem p = coarse_seed_set(set);
    const VoronoiDelaunay first = voronoi_delaunay(p, "fast_marching");
    const RefinedDual r = refine_dual(p, "fast_marching");
    CHECK(r.ok());
    CHECK(r.seeds.leftCols(40) == p.seeds);
    if (first.check.ok()) {
      CHECK(r.added.empty());
      continue;
    }
    ++failing;
    CHECK(dual_faults(p.seeds, first).cols() > 0);
    REQUIRE_FALSE(r.added.empty());
    int added = 0;
    for (const int a : r.added) added += a;
    CHECK(r.seeds.cols() == 40 + added);
    // The new seeds keep their clearance from the old ones.
    for (int s = 40; s < r.seeds.cols(); ++s)
      for (int k = 0; k < s; ++k)
        CHECK((r.seeds.col(s) - r.seeds.col(k)).norm() >= 2 * 0.01 - 1e-12);
  }
  CHECK(failing >= 3);
}

TEST_CASE("a dual that checks needs no refinement", "[voronoi][refine]") {
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({0, 0}, {1, 1}, 151, 151);
  p.seeds.resize(2, 5);
  p.seeds << 0.5, 0.2, 0.82, 0.75, 0.28,  //
      0.48, 0.25, 0.22, 0.8, 0.72;
  RefineOptions no_rounds;
  no_rounds.max_rounds = 0;
  const RefinedDual r = refine_dual(p, "fast_marching", {}, no_rounds);
  CHECK(r.ok());
  CHECK(r.added.empty());
  CHECK(dual_faults(p.seeds, r.result).cols() == 0);
  CHECK(r.result.dual.vertices.cols() == 4);
}

TEST_CASE("no seed is added outside the allowed region or near a segment's diametral circle",
          "[voronoi][refine]") {
  // The failing sets above; every other fault's two nearest seeds made a
  // boundary segment, and only x < 0.5 allowed: each added seed is there and
  // at least circle_cells (0.5) cells outside every segment's circle.
  int added = 0, refused = 0;
  for (unsigned set = 1; set <= 12; ++set) {
    INFO("seed set " << set);
    const VoronoiProblem p = coarse_seed_set(set);
    const Eigen::Matrix2Xd faults = dual_faults(p.seeds, voronoi_delaunay(p, "fast_marching"));
    RefineOptions o;
    for (int f = 0; f < faults.cols(); f += 2) {
      Eigen::VectorXd d = (p.seeds.colwise() - faults.col(f)).colwise().norm().transpose();
      Eigen::Index a = 0, b = 0;
      d.minCoeff(&a);
      d(a) = 1e9;
      d.minCoeff(&b);
      o.segments.push_back({static_cast<int>(a), static_cast<int>(b)});
    }
    o.allowed = [](const Eigen::Vector2d& x) { return x.x() < 0.5; };
    const RefinedDual r = refine_dual(p, "fast_marching", {}, o);
    refused += faults.cols() > 0 && r.added.empty();
    for (int s = 40; s < r.seeds.cols(); ++s) {
      ++added;
      CHECK(r.seeds(0, s) < 0.5);
      for (const auto& [a, b] : o.segments)
        CHECK((r.seeds.col(s) - 0.5 * (p.seeds.col(a) + p.seeds.col(b))).norm() >=
              0.5 * (p.seeds.col(a) - p.seeds.col(b)).norm() + 0.5 * 0.01 - 1e-12);
    }
  }
  CHECK(added > 0);
  CHECK(refused > 0);
}
