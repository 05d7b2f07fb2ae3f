// Gmsh's mesher in a child process: the mesh that comes back is the one Gmsh
// makes in-process (tags, coordinates, parametric coordinates), and a size far
// too small ends in a clear error within the caps instead of a hang.
#include "gmsh/generate_in_child.h"

#include <gmsh.h>

#include <catch2/catch.hpp>
#include <chrono>

#include "../support/gmsh_session.h"
#include "core/error.h"

using homesh::gmsh_adapter::generate_in_child;
using homesh::gmsh_adapter::MeshingLimits;

namespace {

struct MeshDump {
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
};

// Every entity's nodes and elements, in entity order.
std::vector<MeshDump> dump() {
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, -1);
  std::vector<MeshDump> out(entities.size());
  for (std::size_t k = 0; k < entities.size(); ++k) {
    const auto [dim, tag] = entities[k];
    gmsh::model::mesh::getNodes(out[k].node_tags, out[k].coords, out[k].parametric, dim, tag, false,
                                true);
    gmsh::model::mesh::getElements(out[k].types, out[k].element_tags, out[k].element_nodes, dim,
                                   tag);
  }
  return out;
}

MeshingLimits limits(std::size_t max_elements, long seconds) {
  return {max_elements,
          {homesh::gmsh_adapter::default_memory_cap(), std::chrono::seconds(seconds)}};
}

}  // namespace

TEST_CASE("generate_in_child brings back exactly the mesh Gmsh makes in-process", "[gmsh]") {
  homesh::test::GmshSession session;
  homesh::test::make_plate_with_hole(1, 0.1);  // meshed in-process
  const std::vector<MeshDump> direct = dump();
  std::size_t triangles = 0;
  for (const MeshDump& d : direct)
    for (std::size_t k = 0; k < d.types.size(); ++k)
      if (d.types[k] == 2) triangles += d.element_tags[k].size();
  REQUIRE(triangles > 100);

  generate_in_child("plate", limits(1000000, 60));
  const std::vector<MeshDump> child = dump();
  REQUIRE(child.size() == direct.size());
  for (std::size_t k = 0; k < child.size(); ++k) {
    CHECK(child[k].node_tags == direct[k].node_tags);
    CHECK(child[k].coords == direct[k].coords);
    CHECK(child[k].parametric == direct[k].parametric);
    CHECK(child[k].types == direct[k].types);
    CHECK(child[k].element_tags == direct[k].element_tags);
    CHECK(child[k].element_nodes == direct[k].element_nodes);
  }
}

TEST_CASE("generate_in_child stops at the element cap, naming the input and the count", "[gmsh]") {
  homesh::test::GmshSession session;
  homesh::test::make_plate_with_hole(1, 0.1);
  const std::vector<MeshDump> before = dump();
  REQUIRE_THROWS_WITH(generate_in_child("plate.geo", limits(50, 60)),
                      Catch::StartsWith("plate.geo: Gmsh's mesher made ") &&
                          Catch::Contains("more than the limit of 50 (mesh:max_triangles)"));
  CHECK(dump().size() == before.size());
  CHECK(dump()[0].node_tags == before[0].node_tags);  // the model's mesh is left as it was
}

TEST_CASE("generate_in_child stops a mesh size 1e4 times too small at the time cap", "[gmsh]") {
  homesh::test::GmshSession session;
  homesh::test::make_plate_with_hole(1, 0.1);
  gmsh::option::setNumber("Mesh.MeshSizeFactor", 1e-4);
  const auto start = std::chrono::steady_clock::now();
  REQUIRE_THROWS_WITH(generate_in_child("plate.geo", limits(0, 2)),
                      "plate.geo: Gmsh's mesher did not finish within 2 s: are the mesh sizes too "
                      "small? (mesh:max_seconds raises the time limit)");
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
}
