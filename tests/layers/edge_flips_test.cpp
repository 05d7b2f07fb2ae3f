#include "layers/edge_flips.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "layers/radius_ratio.h"

using namespace homesh;

namespace {

// Quad (0,0), (2,0), (2 + s, 1), (s, 1) split along its long diagonal 0-2 (bad for s > 0).
Mesh quad(double s, int second_surface = 1) {
  Mesh m;
  m.x.resize(2, 4);
  m.x << 0, 2, 2 + s, s,  //
      0, 0, 1, 1;
  m.tri.resize(3, 2);
  m.tri << 0, 0,  //
      1, 2,       //
      2, 3;
  m.tri_entity = {1, second_surface};
  return m;
}

}  // namespace

TEST_CASE("edge flips raise the worst radius ratio and keep count and surfaces", "[layers]") {
  Mesh m = quad(1.5);
  const double before = radius_ratios(m).minCoeff();
  REQUIRE(flip_edges(m) == 1);
  const Eigen::VectorXd after = radius_ratios(m);
  CHECK(after.minCoeff() > before + 0.1);
  CHECK(m.num_triangles() == 2);
  CHECK(m.tri_entity == std::vector<int>{1, 1});
  // The new diagonal joins nodes 1 and 3; both triangles counter-clockwise.
  for (int e = 0; e < 2; ++e) {
    CHECK((m.tri.col(e).array() == 1).any());
    CHECK((m.tri.col(e).array() == 3).any());
    const Eigen::Vector2d a = m.x.col(m.tri(0, e)), b = m.x.col(m.tri(1, e)),
                          c = m.x.col(m.tri(2, e));
    CHECK((b - a)(0) * (c - a)(1) - (b - a)(1) * (c - a)(0) > 0);
  }
  CHECK(flip_edges(m) == 0);  // already the better diagonal

  // Restricted to some triangles: only edges shared by two of them flip.
  Mesh part = quad(1.5);
  CHECK(flip_edges(part, std::vector<int>{1}) == 0);
  CHECK(part.tri == quad(1.5).tri);
  CHECK(flip_edges(part, std::vector<int>{0, 1}) == 1);
  CHECK(part.tri == m.tri);
}

TEST_CASE("edge flips leave good diagonals, non-convex quads, surface borders, lines", "[layers]") {
  Mesh good = quad(-1.5);  // the diagonal 0-2 is the short one here
  CHECK(flip_edges(good) == 0);
  // An arrowhead with its reflex corner at node 0: the diagonal 1-3 runs outside.
  Mesh concave = quad(1.5);
  concave.x << 2, 1, 4, 1,  //
      0, -1, 0, 1;
  CHECK(flip_edges(concave) == 0);
  Mesh border = quad(1.5, 2);
  CHECK(flip_edges(border) == 0);
  Mesh embedded = quad(1.5);  // the diagonal carries a line: an embedded curve
  embedded.line.resize(2, 1);
  embedded.line << 2, 0;
  embedded.line_entity = {7};
  CHECK(flip_edges(embedded) == 0);
}

TEST_CASE("edge flips by another quality: the radius ratio in a sheared metric", "[layers]") {
  // quad(-1.5), the parallelogram on (2, 0) and (-1.5, 1), has the better diagonal 0-2 for
  // the radius ratio; mapped by T = [1 3.5; 0 1] (the metric T^T T) it is (0,0), (2,0),
  // (4,1), (2,1), where the other diagonal is the short one.
  Mesh m = quad(-1.5);
  Eigen::Matrix2d T;
  T << 1, 3.5, 0, 1;
  const auto sheared = [&T](const Eigen::Matrix<double, 2, 3>& X) { return radius_ratio(T * X); };
  REQUIRE(flip_edges(m, sheared) == 1);
  CHECK(flip_edges(m, sheared) == 0);
  CHECK(flip_edges(m) == 1);  // back, by the plain radius ratio
}
