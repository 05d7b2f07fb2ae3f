// Regression tests of the homesh command line: run it as a user does and
// assert the numbers in its log and in the files it writes.
#include <gmsh.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <fstream>
#include <regex>
#include <sstream>

#include "../support/gmsh_session.h"
#include "../support/run_command.h"
#include "../support/temp_dir.h"

using homesh::test::run_homesh;
using homesh::test::TempDir;

namespace {

using homesh::test::geo;

bool exists(const std::string& path) { return std::ifstream(path).good(); }

using homesh::test::read;

int number_after(const std::string& text, const std::string& pattern) {
  std::smatch m;
  REQUIRE(std::regex_search(text, m, std::regex(pattern + R"(\s*(\d+))")));
  return std::stoi(m[1]);
}

}  // namespace

TEST_CASE("homesh --list and --help STAGE describe the stages", "[app]") {
  auto r = run_homesh("--list");
  REQUIRE(r.exit_code == 0);
  for (const char* s : {"mesh", "order", "info"}) REQUIRE(r.output.find(s) != std::string::npos);
  r = run_homesh("--help order");
  REQUIRE(r.exit_code == 0);
  REQUIRE(std::regex_search(r.output, std::regex(R"(p\s+2\s+element order, 1 to 10)")));
  r = run_homesh("--help");
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.output.find("INPUT") != std::string::npos);
  REQUIRE(run_homesh("--help nosuch").exit_code != 0);
}

TEST_CASE("NACA-7526 mesh, order 4, info: the issue's command works end to end", "[app]") {
  const TempDir dir;
  const std::string out = dir / "naca.msh";
  const auto r = run_homesh(geo + "naca.geo -m mesh -m order:p=4 -m info " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.output.find("order 4:") != std::string::npos);
  REQUIRE(r.output.find("\"aerofoil\"") != std::string::npos);
  REQUIRE(r.output.find("\"farfield\"") != std::string::npos);
  const int nodes = number_after(r.output, "order 4:");
  const int tris = number_after(r.output, R"(nodes,)");
  REQUIRE(read(out).find("-m order:p=4 -m info") != std::string::npos);

  homesh::test::GmshSession session;
  gmsh::open(out);
  std::vector<std::size_t> tags, elements, element_nodes;
  std::vector<double> coord, param;
  gmsh::model::mesh::getNodes(tags, coord, param);
  REQUIRE(static_cast<int>(tags.size()) == nodes);
  gmsh::model::mesh::getElementsByType(gmsh::model::mesh::getElementType("Triangle", 4), elements,
                                       element_nodes);
  REQUIRE(static_cast<int>(elements.size()) == tris);
  REQUIRE(element_nodes.size() == 15 * elements.size());
  // Every triangle of the written file is valid in Gmsh's own evaluation.
  std::vector<double> local = {1.0 / 3, 1.0 / 3, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0}, jac, det, pts;
  gmsh::model::mesh::getJacobians(gmsh::model::mesh::getElementType("Triangle", 4), local, jac, det,
                                  pts);
  REQUIRE(det.size() == 4 * elements.size());
  REQUIRE(*std::min_element(det.begin(), det.end()) > 0);
}

TEST_CASE("bad input gets a clear error naming it, non-zero exit and no output", "[app]") {
  const TempDir dir;
  const std::string out = dir / "bad.msh";
  struct Case {
    std::string args, message;
  };
  const std::string garbage = dir / "garbage.msh", empty = dir / "empty.geo";
  const std::string missing = dir / "does_not_exist.msh";
  std::ofstream(garbage) << "\x01\x02 this is not a mesh \xff\n";
  std::ofstream(empty).close();
  const std::vector<Case> cases = {
      {missing + " " + out, missing + ": No such file"},
      {empty + " " + out, empty + ": empty file"},
      {garbage + " " + out, garbage},
      {"/etc/hostname " + out, "unknown input kind"},
      {geo + "plate_hole.geo -m order:p=0 " + out, "p=0: out of range [1, 10]"},
      {geo + "plate_hole.geo -m order:p=50 " + out, "p=50: out of range [1, 10]"},
      {geo + "plate_hole.geo -m order:p=nan " + out, "p=nan: not an integer"},
      {geo + "plate_hole.geo -m curvee " + out, "unknown stage 'curvee'"},
      {geo + "plate_hole.geo -m order:q=2 " + out, "unknown option 'q'"},
      {geo + "plate_hole.geo -m mesh:size_max=-1 " + out, "size_max"},
      {geo + "plate_hole.geo /nonexistent/dir/out.msh", "/nonexistent/dir/out.msh"},
  };
  for (const auto& c : cases) {
    const auto r = run_homesh(c.args);
    INFO(c.args << "\n" << r.output);
    REQUIRE(r.exit_code != 0);
    REQUIRE(r.output.find("homesh: error:") != std::string::npos);
    REQUIRE(r.output.find(c.message) != std::string::npos);
    REQUIRE_FALSE(exists(out));
  }
}

namespace {

// A MSH 2.2 file NAME.msh in DIR with 5 nodes and the given element lines ("type nodes...").
std::string msh22(const TempDir& dir, const std::string& name,
                  const std::vector<std::string>& elements) {
  const std::string path = dir / (name + ".msh");
  std::ofstream out(path);
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 1 1 0\n"
         "4 0 1 0\n5 0.5 0 1\n$EndNodes\n$Elements\n"
      << elements.size() << "\n";
  for (std::size_t k = 0; k < elements.size(); ++k) {
    std::istringstream in(elements[k]);
    std::string type, rest;
    in >> type;
    std::getline(in, rest);
    out << k + 1 << " " << type << " 2 0 1" << rest << "\n";
  }
  out << "$EndElements\n";
  return path;
}

}  // namespace

TEST_CASE("every stage's options are checked before the first stage runs", "[app]") {
  // The issue's typo (',' for ':'): refused with stage, option and value, and
  // nothing meshed first.
  const std::string out = "/tmp/homesh_cli_plan.msh";
  std::remove(out.c_str());
  auto r = run_homesh(geo + "naca.geo -m mesh -m curve:p=3,nu=0.3 " + out);
  INFO(r.output);
  REQUIRE(r.exit_code != 0);
  CHECK(r.output.find("homesh: error: stage 'curve': option p=3,nu=0.3: not an integer (options "
                      "are separated by ':', as in curve:p=3:nu=0.3)") != std::string::npos);
  const std::regex mesh_log(R"((^|\n)mesh: )"), order_log(R"((^|\n)order: )");
  CHECK_FALSE(std::regex_search(r.output, mesh_log));
  CHECK(r.output.find("Meshing") == std::string::npos);
  CHECK_FALSE(exists(out));
  // The same for a value out of range in the last stage, after two that would work.
  r = run_homesh(geo + "naca.geo -m mesh -m order:p=2 -m quality:tolerance=2 " + out);
  INFO(r.output);
  REQUIRE(r.exit_code != 0);
  CHECK(r.output.find("stage 'quality': option tolerance=2: out of range (0, 1)") !=
        std::string::npos);
  CHECK_FALSE(std::regex_search(r.output, mesh_log));
  CHECK_FALSE(std::regex_search(r.output, order_log));
  // p=3.0 is the integer 3, p=3.5 is not an integer.
  r = run_homesh(geo + "plate_hole.geo -m order:p=3.0 -m info " + out);
  CHECK(r.exit_code == 0);
  CHECK(r.output.find("\norder: p = 3,") != std::string::npos);
  r = run_homesh(geo + "plate_hole.geo -m order:p=3.5 " + out);
  CHECK(r.exit_code != 0);
  CHECK(r.output.find("stage 'order': option p=3.5: not an integer") != std::string::npos);
  std::remove(out.c_str());
  std::remove((out + ".opt").c_str());
}

TEST_CASE("meshes homesh cannot take are refused with the reason", "[app]") {
  const TempDir dir;
  const std::string out = dir / "badmesh.msh";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {msh22(dir, "quad", {"3 1 4 3 2"}), "quadrilateral 1 at (0.5, 0.5) is inverted"},
      {msh22(dir, "quad8", {"16 1 2 3 4 1 2 3 4"}), "type 'Quadrilateral 8' (Gmsh type 16)"},
      {msh22(dir, "pyramid", {"2 1 2 3", "7 1 2 3 4 5"}), "type 'Pyramid 5' (Gmsh type 7)"},
      {msh22(dir, "flat_tet", {"4 1 2 3 3"}), "tetrahedron 1 repeats a corner node"},
      {msh22(dir, "inverted", {"2 1 2 3", "2 1 4 3"}),
       "triangle 2 at (0.333333, 0.666667) is inverted"},
      {msh22(dir, "duplicate", {"2 1 2 3", "2 2 3 1"}), "duplicates another triangle"},
      {msh22(dir, "lines", {"1 1 2"}), "has no triangles"},
  };
  for (const auto& [in, message] : cases) {
    const auto r = run_homesh(in + " -m info " + out);
    INFO(in << "\n" << r.output);
    REQUIRE(r.exit_code != 0);
    REQUIRE(r.output.find("homesh: error: " + in) != std::string::npos);
    REQUIRE(r.output.find(message) != std::string::npos);
    REQUIRE_FALSE(exists(out));
  }
}

TEST_CASE("stages that do not handle quadrilaterals refuse them, naming stage and type",
          "[app][quads]") {
  const TempDir dir;
  const std::string in = msh22(dir, "square", {"3 1 2 3 4"}), out = dir / "quads_out.msh";
  // One stage through the CLI (tests/pipeline/run_stage_test.cpp checks every stage).
  for (const std::string stage : {"rotate"}) {
    const auto r = run_homesh(in + " -m " + stage + " " + out);
    INFO(r.output);
    REQUIRE(r.exit_code != 0);
    const std::string name = stage.substr(0, stage.find(':'));
    REQUIRE_THAT(r.output, Catch::Contains("stage '" + name +
                                           "' does not handle quadrilaterals yet (mesh has 1 "
                                           "'Quadrilateral 4')"));
    REQUIRE_FALSE(exists(out));
  }
  const auto info = run_homesh(in + " -m info " + out);
  INFO(info.output);
  REQUIRE(info.exit_code == 0);
  REQUIRE_THAT(info.output, Catch::Contains("and 1 quadrilaterals ('Quadrilateral 4')") &&
                                Catch::Contains("validity: 0 invalid of 0 triangles and 1 "
                                                "quadrilaterals"));
  const auto vtu = run_homesh(in + " -m info " + dir / "square.vtu");
  INFO(vtu.output);
  REQUIRE(vtu.exit_code == 0);
  REQUIRE_THAT(vtu.output, Catch::Contains("(order 1, 0 triangles, 1 quadrilaterals, 1 fields)"));
}

TEST_CASE("the same input gives byte-identical output", "[app]") {
  const TempDir dir;
  const std::string out = dir / "determinism.msh";
  const std::string args = geo + "naca.geo -m mesh -m curve:p=3 -m quality " + out;
  REQUIRE(run_homesh(args).exit_code == 0);
  const std::string first = read(out), first_opt = read(out + ".opt");
  REQUIRE(run_homesh(args).exit_code == 0);
  REQUIRE(read(out) == first);
  REQUIRE(read(out + ".opt") == first_opt);
  REQUIRE(first.size() > 100000);
}

TEST_CASE("a failed run leaves the previous output untouched", "[app]") {
  const TempDir dir;
  const std::string out = dir / "keep.msh";
  REQUIRE(run_homesh(geo + "plate_hole.geo -m order:p=2 " + out).exit_code == 0);
  const std::string before = read(out);
  REQUIRE(before.find("$HomeshProvenance") != std::string::npos);
  REQUIRE(run_homesh(geo + "plate_hole.geo -m order:p=99 " + out).exit_code != 0);
  REQUIRE(read(out) == before);
}

TEST_CASE("a .msh input keeps its mesh; -m mesh needs CAD", "[app]") {
  const TempDir dir;
  const std::string first = dir / "first.msh", second = dir / "second.msh";
  auto r = run_homesh(geo + "plate_hole.geo -m mesh -m info " + first);
  REQUIRE(r.exit_code == 0);
  const int nodes = number_after(r.output, "order 1:");
  r = run_homesh(first + " -m info " + second);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  REQUIRE(number_after(r.output, "order 1:") == nodes);
  REQUIRE(r.output.find("CAD: no") != std::string::npos);
  r = run_homesh(first + " -m mesh " + second);
  REQUIRE(r.exit_code != 0);
  REQUIRE(r.output.find("has no CAD geometry") != std::string::npos);
}

TEST_CASE("a CAD input is auto-meshed only when no stage creates a mesh", "[app]") {
  auto r = run_homesh(geo + "plate_hole.geo -m info");
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.output.find("has no mesh: meshing it with the mesh stage's defaults") !=
          std::string::npos);
  for (const char* stage : {"mesh", "voronoi"}) {
    r = run_homesh(geo + "plate_hole.geo -m " + stage + " -m info");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    REQUIRE(r.output.find("has no mesh") == std::string::npos);
  }
}
