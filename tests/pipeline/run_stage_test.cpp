#include <catch2/catch.hpp>
#include <set>
#include <string>

#include "pipeline/stage.h"
#include "pipeline/stage_registry.h"

using namespace homesh;

TEST_CASE("run_stage refuses quadrilaterals to every stage that does not handle them",
          "[pipeline][quads]") {
  Mesh m;  // the unit square as one linear quadrilateral
  m.x.resize(2, 4);
  m.x << 0, 1, 1, 0, 0, 0, 1, 1;
  m.node_class.resize(4);
  m.quad.resize(4, 1);
  m.quad << 0, 1, 2, 3;
  m.quad_entity = {1};
  std::set<std::string> handling;
  for (const Stage& s : stages()) {
    INFO(s.name);
    if (s.handles_quads) {
      handling.insert(s.name);
      continue;
    }
    Context ctx;
    ctx.mesh = m;
    // The check comes before the stage runs, so no options are needed.
    REQUIRE_THROWS_WITH(
        run_stage(s, ctx, std::any()),
        "stage '" + s.name + "' does not handle quadrilaterals yet (mesh has 1 'Quadrilateral 4')");
  }
  // A stage handles them only by decision: these seven (two replace the mesh).
  CHECK(handling ==
        std::set<std::string>{"curve", "info", "mesh", "optimise", "order", "quality", "voronoi"});
}
