#include "layers/open_room.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "../layers/layer_test_meshes.h"
#include "core/error.h"
#include "layers/front_split.h"
#include "quality/mesh_validity.h"

using namespace homesh;

TEST_CASE("fold fraction: when a moving triangle turns flat (Fig 4.5a)", "[layers]") {
  Eigen::Matrix<double, 2, 3> x, u;
  x << 0, 1, 0,  //
      0, 0, 1;
  // One node moving: the distance along its path to the opposite edge's line.
  u << 1, 0, 0,  //
      1, 0, 0;
  CHECK(fold_fraction(x, u) == Approx(0.5));
  u << -1, 0, 0,  //
      0, 0, 0;
  CHECK(fold_fraction(x, u) == std::numeric_limits<double>::infinity());
  // Two nodes moving (quadratic in t): node 1 to (1 - t, 0), node 2 to (0, 1 - t)
  // shrink the triangle to its corner only at t = 1.
  u << 0, -1, 0,  //
      0, 0, -1;
  CHECK(fold_fraction(x, u) == Approx(1));
  // Node 1 swept across the line of the others: flat at t = 1/2 (x = 0).
  u << 0, -2, 0,  //
      0, 0, 0;
  CHECK(fold_fraction(x, u) == Approx(0.5));
  CHECK(fold_fraction(x, Eigen::Matrix<double, 2, 3>::Zero()) ==
        std::numeric_limits<double>::infinity());
}

TEST_CASE("open room: the front of a circular hole pushed radially, capped, valid", "[layers]") {
  // 24 points, hole radius 1, 6 rings to radius 3 with the first ring at 0.0278.
  const Mesh m = test::ring_mesh(test::circle(24, 1), test::circle(24, 3), 6, 2);
  const std::vector<WallLoop> loops = wall_loops(m, {1});
  const std::vector<std::vector<WallNormal>> normals = {wall_normals(m, loops[0])};
  const FrontSplit s = split_front(m, loops, normals);
  REQUIRE(s.gap_triangles == 0);
  REQUIRE(s.mesh.num_nodes() == m.num_nodes() + 24);
  std::vector<int> moving;
  std::vector<bool> fixed(s.mesh.num_nodes());
  for (int i = 0; i < s.mesh.num_nodes(); ++i) fixed[i] = s.mesh.node_class[i].dim < 2;
  for (const auto& f : s.front[0]) moving.push_back(f[0]);

  for (double push : {0.2, 2.5}) {
    CAPTURE(push);
    Eigen::Matrix2Xd target(2, 24);
    for (int k = 0; k < 24; ++k) target.col(k) = (1 + push) * m.x.col(loops[0].nodes[k]);
    const RoomResult r = open_room(s.mesh, moving, target, fixed);
    CHECK(mesh_validity(r.mesh).invalid == 0);
    if (push < 1) {
      // About 7 times the first ring's depth: several capped steps.
      CHECK(r.complete);
      CHECK(r.reached == 1);
      CHECK(r.steps >= 3);
      for (int k = 0; k < 24; ++k) CHECK((r.mesh.x.col(moving[k]) - target.col(k)).norm() == 0);
      for (int i = 0; i < m.num_nodes(); ++i)
        if (fixed[i]) CHECK((r.mesh.x.col(i) - m.x.col(i)).norm() == 0);
    } else {
      // Past the fixed outer circle: stops short, valid, part of the way.
      CHECK(!r.complete);
      CHECK(r.reached > 0.3);
      CHECK(r.reached < 0.8);
      CHECK(r.bottleneck >= 0);
    }
  }
}
