#include "curving/wall_propagation.h"

#include <catch2/catch.hpp>

using namespace homesh;

TEST_CASE(
    "wall propagation: a node follows the nearest wall line's bulge at its projection, "
    "fading to 0 one radius away",
    "[curving]") {
  // One order-2 wall line from (0, 0) to (1, 0), its middle node bulging by (0, 0.1), and
  // free nodes above it.
  Mesh m;
  m.order = 2;
  m.x.resize(2, 7);
  m.x << 0, 1, 0.5, 0.5, 0.25, 0.5, 3,  //
      0, 0, 0, 0.0, 0.5, 2.0, 0;
  m.line.resize(3, 1);
  m.line << 0, 1, 2;
  Eigen::Matrix2Xd target = m.x;
  target.col(2) << 0.5, 0.1;
  std::vector<bool> free = {false, false, false, true, true, true, true};
  m.x(1, 3) = 0.25;  // node 3 at (0.5, 0.25): t = 0.5, r = 0.25 / (1 * 1)
  const Eigen::Matrix2Xd u = propagate_wall_displacement(m, target, free, 1.0);
  const double decay = 1 - 3 * 0.0625 + 2 * 0.015625;
  CHECK(u(0, 3) == Approx(0).margin(1e-15));
  CHECK(u(1, 3) == Approx(0.1 * decay).epsilon(1e-12));
  // (0.25, 0.5): t = 0.25, deviation 4 t (1 - t) 0.1 = 0.075, r = 0.5.
  CHECK(u(1, 4) == Approx(0.075 * 0.5).epsilon(1e-12));
  CHECK(u.col(5).norm() == 0);  // 2 lengths away
  CHECK(u.col(6).norm() == 0);  // beyond the line's end: t = 1, no deviation there
  CHECK(u.col(2).norm() == 0);  // not free
  // Radius 3: node 5 at r = 2/3 moves too.
  const double r = 2.0 / 3;
  CHECK(propagate_wall_displacement(m, target, free, 3.0)(1, 5) ==
        Approx(0.1 * (1 - 3 * r * r + 2 * r * r * r)).epsilon(1e-12));
}

TEST_CASE(
    "wall propagation: wall lines far apart for their length (the cells by hash) move nodes "
    "as lines alone do",
    "[curving]") {
  // The first test's wall line twice, the copy 1e4 lengths away in x and y: their cells'
  // bounding box is 1e7 cells, past the dense grid, so the lines are found by hashing.
  const double far = 1e4;
  Mesh m;
  m.order = 2;
  m.x.resize(2, 10);
  m.x << 0, 1, 0.5, 0.5, 0.25, 0.5, far, far + 1, far + 0.5, far + 0.25,  //
      0, 0, 0, 0.25, 0.5, 2.0, far, far, far, far + 0.5;
  m.line.resize(3, 2);
  m.line << 0, 6, 1, 7, 2, 8;
  Eigen::Matrix2Xd target = m.x;
  target.col(2) << 0.5, 0.1;
  target.col(8) << far + 0.5, far + 0.1;
  std::vector<bool> free(10, false);
  free[3] = free[4] = free[5] = free[9] = true;
  const Eigen::Matrix2Xd u = propagate_wall_displacement(m, target, free, 1.0);
  const double decay = 1 - 3 * 0.0625 + 2 * 0.015625;
  CHECK(u(1, 3) == Approx(0.1 * decay).epsilon(1e-12));
  CHECK(u(1, 4) == Approx(0.075 * 0.5).epsilon(1e-12));
  CHECK(u.col(5).norm() == 0);
  // Node 9 stands to the copy as node 4 to the first line.
  CHECK(u(0, 9) == Approx(0).margin(1e-12));
  CHECK(u(1, 9) == Approx(0.075 * 0.5).epsilon(1e-9));
}
