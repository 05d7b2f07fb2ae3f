#include "voronoi/grid/cartesian_grid.h"

#include <catch2/catch.hpp>

using namespace homesh;

TEST_CASE("a stepped grid starts at lo and reaches hi in steps of ds", "[voronoi]") {
  const CartesianGrid g = CartesianGrid::stepped({-1, 0.5}, {1.05, 1.0}, 0.1);
  CHECK(g.origin == Eigen::Vector2d(-1, 0.5));
  CHECK(g.dx == 0.1);
  CHECK(g.dy == 0.1);
  CHECK(g.nx == 22);  // ceil(2.05 / 0.1) + 1: the last node at 1.1 >= 1.05
  CHECK(g.ny == 6);
  CHECK(g.point(g.nx - 1, g.ny - 1).x() >= 1.05);
}
