#include "pipeline/context.h"

#include <catch2/catch.hpp>

#include "../fem/fem_test_support.h"

using namespace homesh;

// A stage that has the certified validity at hand records it; the summary and the writers
// then bound only what changed since.
TEST_CASE("Context::mesh_validity reuses the recorded validity for the elements still as they were",
          "[pipeline]") {
  Context ctx;
  ctx.input = "test mesh";
  REQUIRE_THROWS_WITH(ctx.mesh_validity(), "the certified validity of test mesh: no mesh");
  Mesh m = fem_test::unit_square(3, 3);
  fem_test::warp(m, 0.05);
  ctx.mesh = m;
  const MeshValidity fresh = homesh::mesh_validity(m);
  CHECK((ctx.mesh_validity().ratio.array() == fresh.ratio.array()).all());

  // Recorded with a made-up ratio, the made-up ratio comes back: it was reused.
  MeshValidity recorded = fresh;
  recorded.ratio(4) = 0.5;
  ctx.certify(recorded);
  CHECK(ctx.mesh_validity().ratio(4) == 0.5);
  CHECK(ctx.certified->mesh.node_class.empty());  // a snapshot of the nodes and elements only

  // A node of element 4 moved: its bounds are computed again, the others still reused.
  ctx.mesh->x.col(ctx.mesh->tri(9, 4)) += Eigen::Vector2d(0.01, 0.0);
  const MeshValidity after = ctx.mesh_validity();
  CHECK(after.ratio(4) == homesh::mesh_validity(*ctx.mesh).ratio(4));
  CHECK(after.ratio(4) != 0.5);
  CHECK(after.ratio(0) == fresh.ratio(0));

  // Other elements (renumbered, as grouping by entity does): all computed again.
  ctx.mesh->tri.col(0).swap(ctx.mesh->tri.col(4));
  CHECK(
      (ctx.mesh_validity().ratio.array() == homesh::mesh_validity(*ctx.mesh).ratio.array()).all());
}
