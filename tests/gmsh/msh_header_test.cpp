// The counts a .msh declares, read from files Gmsh wrote in every version and
// encoding homesh accepts, against the counts Gmsh reports for the same mesh.
#include "gmsh/msh_header.h"

#include <gmsh.h>

#include <catch2/catch.hpp>
#include <fstream>

#include "../support/gmsh_session.h"
#include "../support/temp_dir.h"
#include "core/error.h"

using homesh::gmsh_adapter::read_msh_header;

TEST_CASE("read_msh_header reads the declared counts of MSH 2.2 and 4.1, ASCII and binary",
          "[gmsh]") {
  const homesh::test::GmshSession session;
  const homesh::test::TempDir dir;
  homesh::test::make_plate_with_hole(2);
  gmsh::option::setNumber("Mesh.SaveAll", 1);  // every element, as homesh writes
  std::vector<std::size_t> node_tags;
  std::vector<double> coord, param;
  gmsh::model::mesh::getNodes(node_tags, coord, param);
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes);
  std::size_t elements = 0;
  for (const auto& t : tags) elements += t.size();
  for (const double version : {2.2, 4.1})
    for (const int binary : {0, 1}) {
      gmsh::option::setNumber("Mesh.MshFileVersion", version);
      gmsh::option::setNumber("Mesh.Binary", binary);
      const std::string path = dir / "plate.msh";
      gmsh::write(path);
      const auto h = read_msh_header(path);
      INFO("version " << version << " binary " << binary);
      REQUIRE(h.version == Approx(version));
      REQUIRE(h.binary == (binary == 1));
      REQUIRE(h.nodes == node_tags.size());
      REQUIRE(h.elements == elements);
    }
}

TEST_CASE("read_msh_header refuses what is not a .msh and malformed counts", "[gmsh]") {
  const homesh::test::TempDir dir;
  std::ofstream(dir / "text.msh") << "hello\n";
  REQUIRE_THROWS_WITH(read_msh_header(dir / "text.msh"),
                      Catch::Contains("text.msh") && Catch::Contains("not a Gmsh .msh file"));
  std::ofstream(dir / "bad.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n-3\n";
  REQUIRE_THROWS_WITH(read_msh_header(dir / "bad.msh"), Catch::Contains("$Nodes"));
  std::ofstream(dir / "crlf.msh")
      << "$MeshFormat\r\n2.2 0 8\r\n$EndMeshFormat\r\n$Elements\r\n7\r\n";
  const auto h = read_msh_header(dir / "crlf.msh");
  REQUIRE_FALSE(h.nodes);
  REQUIRE(h.elements == 7u);
}
