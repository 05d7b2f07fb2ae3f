// OUTPUT.vtu from the command line: written like the .msh (certified first,
// atomically), the path checked before any work.
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "../support/run_command.h"
#include "../support/temp_dir.h"

using homesh::test::run_homesh;
using homesh::test::TempDir;

namespace {

using homesh::test::geo;

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// One quadratic triangle whose edge 1-2 node lies beyond corner 0: det J < 0 there.
std::string write_inverted_triangle(const TempDir& dir) {
  const std::string path = dir / "invalid.msh";
  std::ofstream(path) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n6\n1 0 0 0\n2 1 0 0\n"
                         "3 0 1 0\n4 0.5 0 0\n5 -0.2 -0.2 0\n6 0 0.5 0\n$EndNodes\n$Elements\n1\n"
                         "1 9 2 1 1 1 2 3 4 5 6\n$EndElements\n";
  return path;
}

}  // namespace

TEST_CASE("the CLI writes a .vtu with Lagrange cells and the certified minJ/maxJ", "[app][vtu]") {
  const TempDir dir;
  const std::string out = dir / "plate.VTU";  // the extension in any case
  const auto r = run_homesh(geo + "plate_hole.geo -m mesh:factor=4 -m curve:p=3 " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("wrote " + out + " (order 3, 44 triangles, 1 fields)"));
  const std::string vtu = text_of(out);
  CHECK_THAT(vtu, Catch::StartsWith("<?xml version=\"1.0\"?>\n<!--\nhomesh "));
  CHECK_THAT(vtu, Catch::Contains("-m curve:p=3 " + out + "\n-->"));
  CHECK_THAT(vtu, Catch::Contains("NumberOfCells=\"64\""));  // 44 triangles and 20 lines
  CHECK_THAT(vtu, Catch::Contains("Name=\"homesh: certified minJ/maxJ\" NumberOfComponents=\"1\""));
  CHECK_FALSE(std::ifstream(out + ".opt").good());
}

TEST_CASE("an invalid mesh is not written to a .vtu unless asked", "[app][vtu]") {
  const TempDir dir;
  const std::string in = write_inverted_triangle(dir), out = dir / "invalid.vtu";
  auto r = run_homesh(in + " " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 1);
  CHECK_THAT(r.output,
             Catch::Contains(out + ": not written: 1 triangles are not certified valid (keep "
                                   "them with --keep-invalid)"));
  CHECK_FALSE(std::ifstream(out).good());
  r = run_homesh("--keep-invalid " + in + " " + out);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("warning: " + out + ": writing 1 invalid triangles"));
  CHECK(std::ifstream(out).good());
}

TEST_CASE("a bad output path fails naming it before any stage runs", "[app][vtu]") {
  const TempDir dir;
  // The input does not exist: the output's error comes first.
  auto r = run_homesh(dir / "nosuch.geo -m mesh " + dir / "out.vtk");
  REQUIRE(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains(dir / "out.vtk" + ": unknown output format '.vtk' " +
                                       "(homesh writes .msh or .vtu)"));
  CHECK_THAT(r.output, !Catch::Contains("nosuch.geo"));
  r = run_homesh(dir / "nosuch.geo " + dir / "out");
  REQUIRE(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains(dir / "out" + ": no extension to choose the output " +
                                       "format by (homesh writes .msh or .vtu)"));
  r = run_homesh(dir / "nosuch.geo " + dir / "missing/out.vtu");
  REQUIRE(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains("missing/out.vtu") &&
                           Catch::Contains("No such file or directory") &&
                           !Catch::Contains("nosuch.geo"));
  CHECK_THAT(run_homesh("--help").output, Catch::Contains(".vtu: VTK XML UnstructuredGrid"));
}
