#include "voronoi/dual/window_regrowth.h"

#include <catch2/catch.hpp>
#include <vector>

#include "voronoi/dual/conforming_dual.h"
#include "voronoi/dual/refine_dual.h"
#include "voronoi/grid/loop_distance.h"

using namespace homesh;

TEST_CASE("missed segments: boundary pairs that are an edge of no triangle", "[voronoi][window]") {
  const std::vector<std::array<int, 3>> triangles = {{0, 1, 2}, {0, 2, 3}};
  const std::vector<std::array<int, 2>> segments = {{0, 1}, {1, 2}, {2, 4}, {4, 0}, {3, 2}};
  const auto missed = missed_segments(segments, triangles);
  REQUIRE(missed.size() == 2);
  CHECK(missed[0] == std::array<int, 2>{2, 4});
  CHECK(missed[1] == std::array<int, 2>{4, 0});
}

namespace {

// The unit square, boundary seeds 0.1 apart except 0.00625 (0.6 cells of the
// global grid) along the bottom for 0.4 < x < 0.6, interior seeds on a
// lattice 0.1 apart; the dual grown on the global grid.
struct Square {
  Eigen::Matrix2Xd square;
  VoronoiProblem p;
  std::vector<std::array<int, 2>> segments;
  RefinedDual r;

  Square() : square(2, 4) {
    square << 0, 1, 1, 0,  //
        0, 0, 1, 1;
    std::vector<Eigen::Vector2d> seeds;
    for (double x = 0.0; x < 0.4 - 1e-9; x += 0.1) seeds.push_back({x, 0.0});
    for (double x = 0.4; x < 0.6 - 1e-9; x += 0.00625) seeds.push_back({x, 0.0});
    for (double x = 0.6; x < 1.0 - 1e-9; x += 0.1) seeds.push_back({x, 0.0});
    for (double y = 0.0; y < 1.0 - 1e-9; y += 0.1) seeds.push_back({1.0, y});
    for (double x = 1.0; x > 1e-9; x -= 0.1) seeds.push_back({x, 1.0});
    for (double y = 1.0; y > 1e-9; y -= 0.1) seeds.push_back({0.0, y});
    const int boundary = static_cast<int>(seeds.size());
    for (int k = 0; k < boundary; ++k) segments.push_back({k, (k + 1) % boundary});
    for (int j = 1; j < 10; ++j)
      for (int i = 1; i < 10; ++i) seeds.push_back({0.1 * i + (j % 2 ? 0.025 : -0.025), 0.1 * j});

    p.metric = MetricField::constant(400.0 * Eigen::Matrix2d::Identity());  // size 0.05
    p.grid = CartesianGrid::spanning({-0.03, -0.03}, {1.03, 1.03}, 107, 107);
    p.domain = domain_on(p.grid);
    p.seeds.resize(2, static_cast<Eigen::Index>(seeds.size()));
    for (std::size_t k = 0; k < seeds.size(); ++k) p.seeds.col(k) = seeds[k];

    r = refine_dual(p, "fast_marching");
    p.seeds = r.seeds;
  }
  Eigen::VectorXd domain_on(const CartesianGrid& g) const {
    return loop_signed_distance(g, {square}, 8 * g.ds());
  }
  RegrownDual regrow(const WindowOptions& o) const {
    return regrow_windows(
        p, r.result.dual.triangles, r.result.dual.vertices, segments,
        [this](const CartesianGrid& g) { return domain_on(g); }, "fast_marching", o);
  }
};

}  // namespace

TEST_CASE("a finer window where boundary seeds are a cell apart makes the dual conform",
          "[voronoi][window]") {
  const Square s;
  const auto missed = missed_segments(s.segments, s.r.result.dual.triangles);
  INFO("missed by the global grid: " << missed.size());
  CHECK(missed.size() >= 3);
  const RegrownDual w = s.regrow({});
  CHECK(w.windows == 1);
  CHECK(w.finer_windows == 0);
  CHECK(w.window_nodes > 200);
  INFO("window grid " << w.window_nodes << " nodes per side");
  CHECK(missed_segments(s.segments, w.triangles).empty());
  const ConformingTriangulation c = conforming_triangulation(w.seeds, s.segments, w.triangles);
  CHECK(c.filled == 0);
  CHECK(c.dual_dropped == 0);
}

TEST_CASE("a window still missing segments grows again twice as fine", "[voronoi][window]") {
  // A window cell 1.3 times a short segment (0.00625) at first: too coarse;
  // halved until the segments are in the dual, within the node cap.
  const Square s;
  WindowOptions o;
  o.cells = 0.5;
  o.finer = 1.2;
  const RegrownDual w = s.regrow(o);
  INFO("window grid " << w.window_nodes << " nodes per side, " << w.finer_windows << " regrowths");
  CHECK(w.windows == 1);
  CHECK(w.finer_windows >= 1);
  CHECK(w.window_nodes <= o.max_nodes);
  CHECK(missed_segments(s.segments, w.triangles).empty());
  // With the cap at 70 nodes (no finer than the first attempt) some stay missed.
  o.max_nodes = 70;
  const RegrownDual capped = s.regrow(o);
  CHECK(capped.finer_windows == 0);
  CHECK(!missed_segments(s.segments, capped.triangles).empty());
}

TEST_CASE("cluster spots: within reach times the larger size, transitively", "[voronoi][window]") {
  // A chain 0-1-2 (steps 1, size 0.3, reach 4: 1.2 apart at most), 3 far, 4 big enough to
  // reach 3.
  const std::vector<Eigen::Vector2d> p{{0, 0}, {1, 0}, {2, 0}, {10, 0}, {10, 4}};
  const std::vector<double> size{0.3, 0.3, 0.3, 0.1, 1.0};
  const std::vector<std::vector<int>> c = cluster_spots(p, size, 4.0);
  CHECK(c == std::vector<std::vector<int>>{{0, 1, 2}, {3, 4}});
  CHECK(cluster_spots(p, std::vector<double>(5, 0.2), 4.0).size() == 5);
  CHECK(cluster_spots({}, {}, 4.0).empty());
}
