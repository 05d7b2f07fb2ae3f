#include "voronoi/engines/stencil_field.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "../voronoi_test_support.h"

using namespace homesh;

namespace {

// A 70 x 70 grid over the unit square with a hole of radius 0.2 (or no
// domain), under a metric field of anisotropy 8 whose axes turn by pi across
// it (superbases changing often), one constant metric, or a metric per seed.
enum class Metric { field, constant, per_seed };

VoronoiProblem problem(Metric metric, bool hole) {
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({0, 0}, {1, 1}, 70, 70);
  p.seeds = Eigen::Matrix2Xd(2, 2);
  p.seeds << 0.1, 0.9, 0.1, 0.9;
  const Eigen::Matrix2d A = metric_from_axes(0.7, 0.05, 0.05 / 8);
  if (metric == Metric::field) {
    const CartesianGrid coarse = CartesianGrid::spanning({0, 0}, {1, 1}, 6, 6);
    std::vector<Eigen::Matrix2d> M;
    for (int j = 0; j < coarse.ny; ++j)
      for (int i = 0; i < coarse.nx; ++i)
        M.push_back(metric_from_axes(M_PI * (i + j) / 10.0, 0.05, 0.05 / 8));
    p.metric = MetricField(coarse, M);
  } else if (metric == Metric::constant) {
    p.metric = MetricField::constant(A);
  } else {
    p.seed_metrics = {A, metric_from_axes(-0.4, 0.03, 0.01)};
  }
  if (hole) p.domain = test::square_with_hole(p.grid, 48);
  return p;
}

}  // namespace

TEST_CASE("the reverse stencils are exactly the nodes whose stencil reaches a node",
          "[voronoi][fmm]") {
  for (const Metric metric : {Metric::field, Metric::constant, Metric::per_seed}) {
    const VoronoiProblem p = problem(metric, false);
    const StencilField field(p);
    CHECK(field.varying() == (metric == Metric::field));
    const CartesianGrid& g = p.grid;
    for (int s = 0; s < 2; ++s) {
      // Brute force: every node's hexagon, node by node.
      std::vector<std::set<std::pair<int, int>>> expected(g.node_count());
      int changes = 0;
      for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
          const int x = g.index(i, j);
          const LatticeStencil& st = field.stencil(s, x);
          if (i > 0) changes += field.stencil(s, x - 1).base().e1 != st.base().e1;
          for (int k = 0; k < 6; ++k) {
            const Eigen::Vector2i o = st.offset(k);
            const int a = i + o.x(), c = j + o.y();
            if (a >= 0 && c >= 0 && a < g.nx && c < g.ny) expected[g.index(a, c)].insert({x, k});
          }
        }
      if (metric == Metric::field) CHECK(changes > 50);  // the test reaches irregular nodes
      int wrong = 0;
      for (int y = 0; y < g.node_count(); ++y) {
        std::set<std::pair<int, int>> got;
        field.for_each_reverse(s, y, [&](int x, int k) {
          CHECK(got.insert({x, k}).second);  // each once
        });
        wrong += got != expected[y];
      }
      CHECK(wrong == 0);
    }
  }
}

TEST_CASE("a node's passable steps are its stencil's segments that stay in the domain",
          "[voronoi][fmm]") {
  for (const Metric metric : {Metric::field, Metric::constant, Metric::per_seed}) {
    const VoronoiProblem p = problem(metric, true);
    const StencilField field(p);
    const CartesianGrid& g = p.grid;
    int blocked = 0, open = 0;
    for (int s = 0; s < 2; ++s)
      for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
          const int x = g.index(i, j);
          if (!field.inside(x)) continue;
          for (int k = 0; k < 6; ++k) {
            const Eigen::Vector2i o = field.stencil(s, x).offset(k);
            const int a = i + o.x(), c = j + o.y();
            if (a < 0 || c < 0 || a >= g.nx || c >= g.ny) continue;
            const bool traced = field.passable(x, g.index(a, c));
            CHECK(field.passable_step(s, x, k) == traced);
            (traced ? open : blocked) += 1;
          }
        }
    INFO("blocked " << blocked << ", open " << open);
    CHECK(blocked > 20);  // steps across the hole
    CHECK(open > 10000);
  }
}
