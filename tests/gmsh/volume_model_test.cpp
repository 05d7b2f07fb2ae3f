// Volume meshes (issue 24) through the Gmsh adapter: read, raised, written back,
// against Gmsh's own setOrder and AnalyseMeshQuality.
#include <gmsh.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "../support/gmsh_session.h"
#include "core/error.h"
#include "core/raise_volume_order.h"
#include "gmsh/read_volume_model.h"
#include "gmsh/write_volume_model.h"
#include "quality/volume_validity.h"

using namespace homesh;

namespace {

// A unit ball cut out of a box [-2, 2]^3 (OpenCASCADE), physical groups on the
// volume and on the sphere, meshed by Gmsh to tetrahedra of size <= size.
void make_ball_in_box(double size) {
  gmsh::model::add("ball");
  gmsh::model::occ::addBox(-2, -2, -2, 4, 4, 4, 1);
  gmsh::model::occ::addSphere(0, 0, 0, 1, 2);
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  gmsh::model::occ::cut({{3, 1}}, {{3, 2}}, out, map);
  gmsh::model::occ::synchronize();
  gmsh::model::addPhysicalGroup(3, {out[0].second}, 7);
  gmsh::model::setPhysicalName(3, 7, "fluid");
  gmsh::vectorpair surfaces;
  gmsh::model::getBoundary(out, surfaces, false, false, false);
  for (const auto& s : surfaces) {
    std::string type;
    gmsh::model::getType(2, std::abs(s.second), type);
    if (type == "Sphere") gmsh::model::addPhysicalGroup(2, {std::abs(s.second)}, 8);
  }
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  gmsh::model::mesh::generate(3);
}

std::size_t count_elements(int dim) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes, dim, -1);
  std::size_t n = 0;
  for (const auto& t : tags) n += t.size();
  return n;
}

}  // namespace

TEST_CASE("read_volume_model reads Gmsh's tetrahedra, surfaces, curves and groups",
          "[gmsh][volume]") {
  test::GmshSession session;
  make_ball_in_box(0.6);
  std::vector<std::size_t> tags;
  const VolumeMesh m = gmsh_adapter::read_volume_model("ball", &tags);
  CHECK(m.order == 1);
  CHECK(static_cast<std::size_t>(m.num_tetrahedra()) == count_elements(3));
  CHECK(static_cast<std::size_t>(m.num_triangles()) == count_elements(2));
  CHECK(static_cast<std::size_t>(m.num_lines()) == count_elements(1));
  CHECK(tags.size() == static_cast<std::size_t>(m.num_tetrahedra()));
  REQUIRE(m.physicals.size() == 2);
  // Every node Gmsh put on the sphere has its parameters there and lies on it.
  int on_sphere = 0;
  for (int i = 0; i < m.num_nodes(); ++i) {
    const VolumeNodeClass& c = m.node_class[i];
    if (c.dim != 2 || m.x.col(i).norm() > 1.5) continue;
    ++on_sphere;
    CHECK(std::isfinite(c.u));
    CHECK(std::isfinite(c.v));
    CHECK(m.x.col(i).norm() == Approx(1.0).margin(1e-9));
  }
  CHECK(on_sphere > 20);
}

TEST_CASE("raise_volume_order makes as many nodes as Gmsh setOrder, and writes back to Gmsh",
          "[gmsh][volume]") {
  for (int p = 2; p <= 4; ++p) {
    CAPTURE(p);
    test::GmshSession session;
    make_ball_in_box(0.8);
    const VolumeMesh linear = gmsh_adapter::read_volume_model("ball");
    const VolumeMesh r = raise_volume_order(linear, p);
    gmsh::model::mesh::setOrder(p);
    std::vector<std::size_t> node_tags;
    std::vector<double> xyz, param;
    gmsh::model::mesh::getNodes(node_tags, xyz, param);
    CHECK(static_cast<std::size_t>(r.num_nodes()) == node_tags.size());

    // Written into the model and read back: the same mesh, groups and all.
    const gmsh_adapter::ModelTags written = gmsh_adapter::write_volume_model(r);
    CHECK(written.element.size() == static_cast<std::size_t>(r.num_tetrahedra()));
    const VolumeMesh back = gmsh_adapter::read_volume_model("written");
    CHECK(back.order == p);
    CHECK(back.x == r.x);
    CHECK(back.tet == r.tet);
    CHECK(back.tri == r.tri);
    CHECK(back.line == r.line);
    CHECK(back.physicals.size() == 2);
    // Gmsh's element tags are those VolumeMesh::tetrahedron_tag gives.
    int type = 0;
    std::vector<std::size_t> nodes;
    gmsh::model::mesh::getElement(r.tetrahedron_tag(r.num_tetrahedra() - 1), type, nodes);
    CHECK(type == gmsh::model::mesh::getElementType("Tetrahedron", p));
    CHECK(nodes.front() == static_cast<std::size_t>(r.tet(0, r.num_tetrahedra() - 1)) + 1);

    // Straight-sided: Gmsh's AnalyseMeshQuality and ours give 1 everywhere.
    std::vector<std::size_t> element_tags;
    std::vector<std::vector<double>> data;
    gmsh::plugin::setNumber("AnalyseMeshQuality", "DimensionOfElements", 3);
    REQUIRE(test::analyse_mesh_quality(element_tags, data));
    double gmsh_worst = 1;
    for (const auto& d : data) gmsh_worst = std::min(gmsh_worst, d[0]);
    CHECK(gmsh_worst == Approx(1.0).margin(1e-6));
    const MeshValidity v = volume_validity(r);
    CHECK(v.invalid == 0);
    CHECK(v.worst == Approx(1.0).margin(1e-9));
  }
}

TEST_CASE("read_volume_model refuses hexahedra, naming the type, and models without tetrahedra",
          "[gmsh][volume]") {
  test::GmshSession session;
  gmsh::model::add("hexes");
  gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.5);
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  gmsh::option::setNumber("Mesh.Recombine3DAll", 1);
  gmsh::option::setNumber("Mesh.Algorithm3D", 1);
  gmsh::model::mesh::setTransfiniteAutomatic();
  gmsh::model::mesh::generate(3);
  CHECK_THROWS_WITH(gmsh_adapter::read_volume_model("hexes.msh"),
                    Catch::Contains("hexes.msh: has elements of type 'Quadrilateral 4'") ||
                        Catch::Contains("'Hexahedron 8'"));
  gmsh::model::add("surface");
  gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.RecombineAll", 0);
  gmsh::model::mesh::generate(2);
  CHECK_THROWS_WITH(gmsh_adapter::read_volume_model("surface.msh"),
                    Catch::Contains("surface.msh: has no tetrahedra"));
}
