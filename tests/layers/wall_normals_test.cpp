#include "layers/wall_normals.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "../layers/layer_test_meshes.h"
#include "core/error.h"
#include "layers/wall_loops.h"

using namespace homesh;

namespace {

double signed_area(const Mesh& m, const WallLoop& loop) {
  double a = 0;
  const std::size_t n = loop.nodes.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d p = m.x.col(loop.nodes[i]), q = m.x.col(loop.nodes[(i + 1) % n]);
    a += 0.5 * (p(0) * q(1) - p(1) * q(0));
  }
  return a;
}

// A 4 x 4 grid of cells (side 2) with a 2 x 2 hole in the middle (side 1).
Mesh normals_box_with_hole() {
  return test::grid_mesh(
      4, 4, 0.5, [](int i, int j) { return !(i >= 1 && i <= 2 && j >= 1 && j <= 2); },
      [](const Eigen::Vector2d& p) {
        return p(0) > 0.4 && p(0) < 1.6 && p(1) > 0.4 && p(1) < 1.6;
      });
}

}  // namespace

TEST_CASE("wall normal: bisector and miter at straight, right and re-entrant nodes", "[layers]") {
  const Eigen::Vector2d o(0, 0);
  // Straight wall along +x, domain above.
  WallNormal w = wall_normal({-1, 0}, o, {1, 0});
  CHECK(w.angle == Approx(M_PI));
  REQUIRE(w.directions.size() == 1);
  CHECK((w.directions[0] - Eigen::Vector2d(0, 1)).norm() < 1e-15);
  CHECK(w.scale == Approx(1));
  // Convex corner of the domain (90 deg): bisector into the corner, miter sqrt 2.
  w = wall_normal({0, 1}, o, {1, 0});
  CHECK(w.angle == Approx(M_PI / 2));
  CHECK((w.directions[0] - Eigen::Vector2d(1, 1).normalized()).norm() < 1e-15);
  CHECK(w.scale == Approx(std::sqrt(2)));
  // Re-entrant corner (270 deg): bisector out of the corner, miter sqrt 2.
  w = wall_normal({1, 0}, o, {0, 1});
  CHECK(w.angle == Approx(1.5 * M_PI));
  CHECK((w.directions[0] - Eigen::Vector2d(-1, -1).normalized()).norm() < 1e-15);
  CHECK(w.scale == Approx(std::sqrt(2)));
  // A sharp 20 deg wedge (domain angle 340 deg): the miter is capped.
  const double half = 10 * M_PI / 180;
  w = wall_normal({-std::cos(half), std::sin(half)}, o, {-std::cos(half), -std::sin(half)});
  CHECK(w.angle == Approx(2 * M_PI - 2 * half));
  CHECK((w.directions[0] - Eigen::Vector2d(1, 0)).norm() < 1e-14);
  CHECK(w.scale == Approx(std::sqrt(2)));
}

TEST_CASE("wall normal: a fan of equal angles from one edge's normal to the other's", "[layers]") {
  const double half = 10 * M_PI / 180;  // domain angle 340 deg
  const Eigen::Vector2d prev(-std::cos(half), std::sin(half)),
      next(-std::cos(half), -std::sin(half));
  NormalOptions opt;
  opt.multi = true;
  for (int fan : {3, 5, 7}) {
    opt.fan = fan;
    const WallNormal w = wall_normal(prev, {0, 0}, next, opt);
    REQUIRE(static_cast<int>(w.directions.size()) == fan);
    CHECK(w.scale == 1);
    // First normal perpendicular to the outgoing edge, last to the incoming one.
    CHECK(std::abs(w.directions.front().dot(next)) < 1e-14);
    CHECK(std::abs(w.directions.back().dot(prev)) < 1e-14);
    CHECK((w.directions[fan / 2] - Eigen::Vector2d(1, 0)).norm() < 1e-14);
    const double step = (2 * M_PI - 2 * half - M_PI) / (fan - 1);
    for (int j = 0; j + 1 < fan; ++j)
      CHECK(std::acos(w.directions[j].dot(w.directions[j + 1])) == Approx(step));
  }
  opt.fan_angle = 345;  // above this node's 340 deg: a single normal again
  CHECK(wall_normal(prev, {0, 0}, next, opt).directions.size() == 1);
  opt.fan = 4;
  CHECK_THROWS_WITH(wall_normal(prev, {0, 0}, next, opt), Catch::Contains("odd"));
  opt.fan = 5;
  opt.fan_angle = 120;
  CHECK_THROWS_WITH(wall_normal(prev, {0, 0}, next, opt), Catch::Contains("[180, 360)"));
}

TEST_CASE("wall loops and normals of a circle: radial, the domain on the left", "[layers]") {
  const Mesh m = test::ring_mesh(test::circle(24, 1), test::circle(24, 3), 4);
  const auto loops = wall_loops(m, wall_curves(m, {"wall", "outer"}));
  REQUIRE(loops.size() == 2);
  for (const WallLoop& loop : loops) {
    REQUIRE(loop.nodes.size() == 24);
    const bool hole = m.x.col(loop.nodes[0]).norm() < 2;
    // The hole runs clockwise, the outer boundary counter-clockwise.
    CHECK(signed_area(m, loop) ==
          Approx(hole ? -12 * std::sin(2 * M_PI / 24) : 9 * 12 * std::sin(2 * M_PI / 24)));
    const auto normals = wall_normals(m, loop);
    for (std::size_t i = 0; i < loop.nodes.size(); ++i) {
      const Eigen::Vector2d radial = m.x.col(loop.nodes[i]).normalized();
      CHECK((normals[i].directions[0] - (hole ? radial : Eigen::Vector2d(-radial))).norm() < 1e-14);
      CHECK(normals[i].angle == Approx(hole ? M_PI + 2 * M_PI / 24 : M_PI - 2 * M_PI / 24));
      CHECK(normals[i].scale == Approx(1 / std::cos(M_PI / 24)));
    }
  }
}

TEST_CASE("wall loops and normals of a square hole in a square box", "[layers]") {
  const Mesh m = normals_box_with_hole();
  const auto loops = wall_loops(m, wall_curves(m, {"1", "outer"}));
  REQUIRE(loops.size() == 2);
  int corners = 0;
  for (const WallLoop& loop : loops) {
    const bool hole = loop.curves[0] == 1;
    CHECK(loop.nodes.size() == (hole ? 8u : 16u));
    CHECK(signed_area(m, loop) == Approx(hole ? -1 : 4));
    NormalOptions bisectors;  // the grid's corners are on curves, not CAD points: unblended
    bisectors.blend = 0;
    const auto normals = wall_normals(m, loop, bisectors);
    for (std::size_t i = 0; i < loop.nodes.size(); ++i) {
      const Eigen::Vector2d p = m.x.col(loop.nodes[i]);
      const Eigen::Vector2d c(1, 1);
      const Eigen::Vector2d n = normals[i].directions[0];
      if (std::abs(std::abs(p(0) - 1) - std::abs(p(1) - 1)) < 1e-12) {  // a corner
        ++corners;
        CHECK(normals[i].angle == Approx(hole ? 1.5 * M_PI : 0.5 * M_PI));
        const Eigen::Vector2d diagonal = (hole ? p - c : c - p).normalized();
        CHECK((n - diagonal).norm() < 1e-14);
      } else {
        CHECK(normals[i].angle == Approx(M_PI));
        CHECK(normals[i].scale == Approx(1));
        CHECK(std::abs(n.dot(Eigen::Vector2d(1, 1))) == Approx(1));  // axis-aligned
      }
    }
  }
  CHECK(corners == 8);
}

TEST_CASE("wall loops refuse unknown names and interfaces, chain open walls", "[layers]") {
  const Mesh m = normals_box_with_hole();
  CHECK_THROWS_WITH(wall_curves(m, {"aerofoil"}),
                    Catch::Contains("no wall 'aerofoil'") && Catch::Contains("wall, outer"));
  CHECK_THROWS_WITH(wall_curves(m, {"7"}), Catch::Contains("no wall '7'"));
  // The bottom side of the box and the lowest lines of its sides: an open chain
  // from (0, 0.5) to (2, 0.5) ending on the sides' other lines.
  Mesh open = m;
  for (int k = 0; k < open.num_lines(); ++k)
    if (open.line_entity[k] == 2 && open.x(1, open.line(0, k)) != 0 &&
        open.x(1, open.line(1, k)) != 0)
      open.line_entity[k] = 3;
  const auto chain = wall_loops(open, {2});
  REQUIRE(chain.size() == 1);
  CHECK_FALSE(chain[0].closed);
  CHECK(chain[0].edges() == 6);
  CHECK((open.x.col(chain[0].prev(0)) - Eigen::Vector2d(0, 1)).norm() == 0);
  CHECK((open.x.col(chain[0].next(6)) - Eigen::Vector2d(2, 1)).norm() == 0);
  CHECK(open.line_entity[chain[0].end_lines[0]] == 3);
  // A line between two triangles is an interface, not a wall.
  Mesh inner = m;
  inner.line.col(0) << inner.tri(0, 0), inner.tri(2, 0);
  CHECK_THROWS_WITH(wall_loops(inner, {1, 2}), Catch::Contains("bounds 2 triangles"));
}

namespace {

// The wall round a body: n nodes clockwise on the unit circle (the domain
// outside, on the left), node 0 pushed out to radius `bump`.
std::pair<Mesh, WallLoop> body_loop(int n, double bump) {
  Mesh m;
  m.x.resize(2, n);
  WallLoop loop;
  for (int i = 0; i < n; ++i) {
    const double a = -2 * M_PI * i / n;
    m.x.col(i) = (i == 0 ? bump : 1.0) * Eigen::Vector2d(std::cos(a), std::sin(a));
    loop.nodes.push_back(i);
  }
  return {m, loop};
}

double angle_between(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::acos(std::clamp(a.dot(b), -1.0, 1.0));
}

}  // namespace

TEST_CASE("blended normals: unchanged on a circle, smoother at a bump, depth kept", "[layers]") {
  NormalOptions bisectors, blended;
  bisectors.blend = 0;
  blended.blend = 5;
  {
    const auto [m, loop] = body_loop(24, 1);
    const auto own = wall_normals(m, loop, bisectors), smooth = wall_normals(m, loop, blended);
    for (int i = 0; i < 24; ++i) {
      CHECK((own[i].directions[0] - smooth[i].directions[0]).norm() < 1e-12);
      CHECK(own[i].scale == Approx(smooth[i].scale).epsilon(1e-12));
    }
  }
  // Node 0 out at 1.5: the wall turns by about 60 deg there and bends back at its
  // neighbours, so the bisectors jump; blended, they turn more gradually.
  const auto [m, loop] = body_loop(24, 1.5);
  const auto own = wall_normals(m, loop, bisectors), smooth = wall_normals(m, loop, blended);
  double jump_own = 0, jump_smooth = 0;
  for (int i = 0; i < 24; ++i) {
    const int j = (i + 1) % 24;
    jump_own = std::max(jump_own, angle_between(own[i].directions[0], own[j].directions[0]));
    jump_smooth =
        std::max(jump_smooth, angle_between(smooth[i].directions[0], smooth[j].directions[0]));
    // Within 30 deg of the bisector; the layers keep their depth from both edges' lines.
    CHECK(angle_between(own[i].directions[0], smooth[i].directions[0]) <= M_PI / 6 + 1e-12);
    const Eigen::Vector2d x = m.x.col(i), t = (m.x.col(loop.next(i)) - x).normalized();
    const Eigen::Vector2d in = (m.x.col(loop.prev(i)) - x).normalized();
    const Eigen::Vector2d step = smooth[i].scale * smooth[i].directions[0];
    const double from_out = t.x() * step.y() - t.y() * step.x();   // distance to the outgoing line
    const double from_in = step.x() * in.y() - step.y() * in.x();  // to the incoming line
    if (smooth[i].scale < M_SQRT2) {
      CHECK(std::min(from_out, from_in) == Approx(1).epsilon(1e-12));
    } else {
      CHECK(std::min(from_out, from_in) <= 1 + 1e-12);
    }
  }
  // The bump's own node keeps its bisector (symmetry).
  CHECK((own[0].directions[0] - smooth[0].directions[0]).norm() < 1e-12);
  CHECK(jump_own > 0.5);
  CHECK(jump_smooth < 0.6 * jump_own);
}
