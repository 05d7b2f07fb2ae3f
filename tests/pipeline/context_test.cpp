#include "pipeline/context.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "../fem/fem_test_support.h"
#include "core/raise_volume_order.h"
#include "quality/volume_validity.h"

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

TEST_CASE(
    "Context::volume_validity reuses the recorded validity for the tetrahedra still as they were",
    "[pipeline]") {
  Context ctx;
  ctx.input = "test volume";
  REQUIRE_THROWS_WITH(ctx.volume_validity(),
                      "the certified validity of test volume: no tetrahedra");
  // Two tetrahedra sharing a face, raised to p = 3 and their new nodes nudged.
  VolumeMesh m;
  m.x.resize(3, 5);
  m.x << 0.0, 2.0, 0.3, 0.2, 1.4,  //
      0.0, 0.1, 1.7, 0.4, 1.2,     //
      0.0, 0.0, 0.1, 1.6, 1.5;
  m.node_class.assign(5, {3, 1});
  m.tet.resize(4, 2);
  m.tet << 0, 2, 1, 3, 2, 1, 3, 4;
  m.tet_entity = {1, 1};
  m = raise_volume_order(m, 3);
  for (int i = 5; i < m.num_nodes(); ++i) m.x(0, i) += 0.01 * std::sin(i);
  ctx.volume = m;
  const MeshValidity fresh = homesh::volume_validity(m);
  CHECK((ctx.volume_validity().ratio.array() == fresh.ratio.array()).all());

  // Recorded with made-up ratios, they come back: reused.
  MeshValidity recorded = fresh;
  recorded.ratio.setConstant(0.5);
  ctx.certify_volume(recorded);
  CHECK(ctx.volume_validity().ratio(0) == 0.5);
  CHECK(ctx.volume_certified->mesh.node_class.empty());  // nodes and tetrahedra only

  // A node only tetrahedron 1 has moved: it is bounded again, tetrahedron 0 still reused.
  ctx.volume->x.col(ctx.volume->tet(3, 1)) += Eigen::Vector3d(0.0, 0.0, 0.05);
  const MeshValidity after = ctx.volume_validity();
  CHECK(after.ratio(0) == 0.5);
  CHECK(after.ratio(1) == homesh::volume_validity(*ctx.volume).ratio(1));
  CHECK(after.ratio(1) != 0.5);
  // Another order: all bounded again.
  ctx.volume = raise_volume_order(*ctx.volume, 2);
  CHECK((ctx.volume_validity().ratio.array() == homesh::volume_validity(*ctx.volume).ratio.array())
            .all());
}
