#include "quality/mesh_validity.h"

#include <catch2/catch.hpp>

#include "../fem/fem_test_support.h"
#include "validity_test_support.h"

using namespace homesh;

using homesh::test::require_same_validity;

TEST_CASE("mesh_validity from a known state bounds only the moved elements, to the same numbers",
          "[quality]") {
  Mesh before = fem_test::unit_square(4, 3);
  fem_test::warp(before, 0.05);
  BoundsOptions opt;
  opt.max_subdivisions = 3;  // some elements left unconverged: their flags must carry over
  const MeshValidity known = mesh_validity(before, opt);

  Mesh after = before;
  // One element made invalid (an interior node pushed out of it), one edge node nudged.
  after.x.col(after.tri(9, 0)) += Eigen::Vector2d(0.4, -0.3);
  after.x.col(after.tri(4, 7)) += Eigen::Vector2d(0.01, 0.02);
  const MeshValidity fresh = mesh_validity(after, opt);
  REQUIRE(fresh.invalid >= 1);
  require_same_validity(mesh_validity(after, before, known, opt), fresh);
  require_same_validity(mesh_validity(after, {&before, &known}, opt), fresh);
  require_same_validity(mesh_validity(before, before, known, opt), known);

  // Reuse needs the same bounds options and the same elements: otherwise all are bounded again.
  BoundsOptions finer = opt;
  finer.relative_tolerance = 1e-5;
  finer.max_subdivisions = 1000;
  require_same_validity(mesh_validity(after, before, known, finer), mesh_validity(after, finer));
  Mesh renumbered = after;
  renumbered.tri.col(0).swap(renumbered.tri.col(1));
  require_same_validity(mesh_validity(renumbered, before, known, opt),
                        mesh_validity(renumbered, opt));
  require_same_validity(mesh_validity(after, {nullptr, &known}, opt), fresh);

  // The known bounds are copied, not recomputed: a made-up ratio of an element that did
  // not move comes back (the caller vouches for `known`).
  MeshValidity stale = known;
  stale.ratio(3) = 0.5;
  CHECK(mesh_validity(before, before, stale, opt).ratio(3) == 0.5);
}

TEST_CASE("certified_better: fewer invalid elements first, then a higher worst",
          "[quality][mesh_validity]") {
  CHECK(certified_better(1, -0.5, 2, 0.9));  // fewer invalid, whatever the worst
  CHECK_FALSE(certified_better(2, 0.9, 1, -0.5));
  CHECK(certified_better(0, 0.51, 0, 0.5));       // as many: the higher worst
  CHECK_FALSE(certified_better(0, 0.5, 0, 0.5));  // equal is not better
  CHECK_FALSE(certified_better(3, -0.2, 3, -0.1));
}
