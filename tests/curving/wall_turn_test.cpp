#include "curving/wall_turn.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <utility>

using namespace homesh;

namespace {

// A closed polygon of n lines round the unit circle on curve 1 (its first node on
// model point 1, where the curve closes), then a straight line of 4 lines on curve 2
// leaving that point at a right angle (a junction of three lines there).
Mesh circle_and_tail(int n) {
  Mesh m;
  m.x.resize(2, n + 4);
  m.node_class.resize(n + 4);
  m.line.resize(2, n + 4);
  for (int i = 0; i < n; ++i) {
    m.x.col(i) << std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n);
    m.node_class[i] = {i == 0 ? 0 : 1, 1};
    // Lines listed out of order and some reversed: the turn depends on neither.
    const int k = (3 * i) % n;  // n is not a multiple of 3 below: k runs over all lines
    m.line.col(k) << i, (i + 1) % n;
    if (k % 2) m.line.col(k).reverseInPlace();
  }
  m.line_entity.assign(n, 1);
  for (int j = 0; j < 4; ++j) {
    m.x.col(n + j) << 1 + 0.25 * (j + 1), 0;
    m.node_class[n + j] = {j == 3 ? 0 : 1, 2};
    m.line.col(n + j) << (j == 0 ? 0 : n + j - 1), n + j;
    m.line_entity.push_back(2);
  }
  return m;
}

// Arcs of the unit circle (u the angle) and straight segments (u in [0, 1]).
class Curves : public CurveEvaluator {
 public:
  std::map<int, std::pair<Eigen::Vector2d, Eigen::Vector2d>> segments;  // the rest are arcs
  bool slides(int) const override { return true; }
  CurveRange range(int) const override { return {}; }
  Eigen::Vector2d point(int tag, double u, Eigen::Vector2d* tangent) const override {
    const auto s = segments.find(tag);
    if (s != segments.end()) {
      if (tangent) *tangent = s->second.second - s->second.first;
      return s->second.first + u * (s->second.second - s->second.first);
    }
    if (tangent) *tangent << -std::sin(u), std::cos(u);
    return {std::cos(u), std::sin(u)};
  }
  double parameter(int tag, const Eigen::Vector2d& x) const override {
    const auto s = segments.find(tag);
    if (s == segments.end()) return std::atan2(x.y(), x.x());
    const Eigen::Vector2d d = s->second.second - s->second.first;
    return (x - s->second.first).dot(d) / d.squaredNorm();
  }
};

}  // namespace

TEST_CASE("largest_wall_turn without CAD: 360 / n degrees round a circle, corners left out",
          "[curving]") {
  for (int n : {5, 11, 25}) {
    // The junction where the line leaves the circle counts for nothing.
    CHECK(largest_wall_turn(circle_and_tail(n), nullptr, 180) == Approx(360.0 / n).epsilon(1e-12));
    // Turns of corner_degrees or more are the rebuilt boundary's corners: none counts.
    CHECK(largest_wall_turn(circle_and_tail(n), nullptr, 40) ==
          Approx(n == 5 ? 0 : 360.0 / n).margin(1e-12));
  }
  // One node pushed out of the circle by a fifth: its turn is the largest.
  Mesh bump = circle_and_tail(11);
  bump.x.col(4) *= 1.2;
  const Eigen::Vector2d d1 = bump.x.col(4) - bump.x.col(3), d2 = bump.x.col(5) - bump.x.col(4);
  CHECK(largest_wall_turn(bump, nullptr, 180) ==
        Approx(std::acos(d1.dot(d2) / (d1.norm() * d2.norm())) * 180 / M_PI).epsilon(1e-12));
  // The circle's lines from that node on moved to curve 3: the rebuilt boundary keeps a
  // corner where the curves change (rebuilt_corner), so that turn no longer counts, only
  // the polygon's 360 / 11 elsewhere.
  Mesh split = bump;
  for (int k = 0; k < 11; ++k)
    if (std::min(split.line(0, k), split.line(1, k)) >= 4) split.line_entity[k] = 3;
  CHECK(largest_wall_turn(split, nullptr, 180) == Approx(360.0 / 11).epsilon(1e-12));
}

TEST_CASE("largest_wall_turn with CAD: smooth joins of curves count, corners do not", "[curving]") {
  Curves curves;
  // A circle of three arcs (curves 1-3), each one line: the lines turn by 120 degrees at
  // the model points where the arcs join smoothly.
  Mesh tri;
  tri.x.resize(2, 3);
  tri.node_class.assign(3, {0, 1});
  for (int i = 0; i < 3; ++i) {
    const double a = M_PI / 2 + 2 * M_PI * i / 3;
    tri.x.col(i) << std::cos(a), std::sin(a);
  }
  tri.line.resize(2, 3);
  tri.line << 0, 1, 2, 1, 2, 0;
  tri.line_entity = {1, 2, 3};
  CHECK(largest_wall_turn(tri, &curves, 40) == Approx(120).epsilon(1e-12));
  // A D: the upper half circle (curve 1, 4 lines: 45 degrees inside) and its diameter
  // (curve 2, 2 lines), meeting at right angles (112.5 degrees between the lines) at the
  // model points (1, 0) and (-1, 0).
  curves.segments[2] = {Eigen::Vector2d(-1, 0), Eigen::Vector2d(1, 0)};
  Mesh d;
  d.x.resize(2, 6);
  d.node_class.resize(6);
  for (int i = 0; i < 5; ++i) {
    d.x.col(i) << std::cos(M_PI * i / 4), std::sin(M_PI * i / 4);
    d.node_class[i] = {i == 0 || i == 4 ? 0 : 1, i == 0 || i == 4 ? i + 1 : 1};
  }
  d.x.col(5) << 0, 0;
  d.node_class[5] = {1, 2};
  d.line.resize(2, 6);
  d.line << 0, 1, 2, 3, 4, 5,  //
      1, 2, 3, 4, 5, 0;
  d.line_entity = {1, 1, 1, 1, 2, 2};
  CHECK(largest_wall_turn(d, &curves, 180) == Approx(45).epsilon(1e-12));
}
