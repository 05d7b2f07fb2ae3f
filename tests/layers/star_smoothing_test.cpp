#include "layers/star_smoothing.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "layers/radius_ratio.h"

using namespace homesh;

namespace {

// A regular hexagon of radius 1 around node 6 at (x, y): six counter-clockwise triangles.
Mesh hexagon(double x, double y) {
  Mesh m;
  m.x.resize(2, 7);
  for (int k = 0; k < 6; ++k) m.x.col(k) << std::cos(k * M_PI / 3), std::sin(k * M_PI / 3);
  m.x.col(6) << x, y;
  m.tri.resize(3, 6);
  for (int k = 0; k < 6; ++k) m.tri.col(k) << 6, k, (k + 1) % 6;
  m.tri_entity.assign(6, 1);
  return m;
}

}  // namespace

TEST_CASE("star quality: the worst radius ratio around each node, -1 if one is clockwise",
          "[layers]") {
  const Mesh centred = hexagon(0, 0);
  const std::vector<double> q = star_quality(centred);
  CHECK(q[6] == Approx(1));  // six equilateral triangles
  CHECK(q[0] == Approx(1));
  CHECK(star_quality(hexagon(0.9, 0.5))[6] == -1);  // past the edge from node 0 to node 1
}

TEST_CASE("star smoothing: a squeezed node goes back towards its neighbours' centroid",
          "[layers]") {
  // Node 6 squeezed to 0.02 below the edge (0, 1): a nearly flat triangle there.
  const Eigen::Vector2d edge_mid =
      (Eigen::Vector2d(1, 0) + Eigen::Vector2d(0.5, std::sqrt(0.75))) / 2;
  const Eigen::Vector2d squeezed = edge_mid * (1 - 0.02 / edge_mid.norm());
  Mesh m = hexagon(squeezed.x(), squeezed.y());
  const double before = star_quality(m)[6];
  REQUIRE(before < 0.1);
  std::vector<bool> movable(7, false);
  movable[6] = true;

  SECTION("below its floor it moves, and its worst Q rises to the centred star's") {
    Mesh s = m;
    const int moves = smooth_stars(s, movable, std::vector<double>(7, 0.9));
    CHECK(moves >= 1);
    CHECK(s.x.col(6).norm() < 1e-12);  // the centroid of a regular hexagon: its centre
    CHECK(star_quality(s)[6] == Approx(1));
    CHECK((s.x.leftCols(6) - m.x.leftCols(6)).norm() == 0);
    CHECK(radius_ratios(s).minCoeff() > before);
  }
  SECTION("at or above its floor, or not movable, it stays") {
    Mesh s = m;
    CHECK(smooth_stars(s, movable, std::vector<double>(7, before)) == 0);
    CHECK(smooth_stars(s, std::vector<bool>(7, false), std::vector<double>(7, 0.9)) == 0);
    CHECK((s.x - m.x).norm() == 0);
  }
}
