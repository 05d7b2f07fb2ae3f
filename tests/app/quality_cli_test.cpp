// The quality stage and the validity guard on output, run as a user does.
#include <gmsh.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <regex>

#include "../support/gmsh_session.h"
#include "../support/run_command.h"
#include "../support/temp_dir.h"
#include "gmsh/read_model.h"
#include "gmsh/write_model.h"

using homesh::test::run_homesh;
using homesh::test::TempDir;

namespace {

const std::string geo = std::string(HOMESH_SOURCE_DIR) + "/geo/";

// A quadratic plate-with-hole mesh with one interior edge node pushed far
// across its triangles, written in DIR: corners fine, curved elements invalid.
std::string write_invalid_mesh(const TempDir& dir) {
  const std::string path = dir / "invalid_input.msh";
  homesh::test::GmshSession session;
  gmsh::open(geo + "plate_hole.geo");
  gmsh::model::mesh::generate(2);
  gmsh::model::mesh::setOrder(2);
  homesh::Mesh m = homesh::gmsh_adapter::read_model("plate");
  std::vector<bool> corner(m.num_nodes(), false);
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int k = 0; k < 3; ++k) corner[m.tri(k, e)] = true;
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_class[i].dim == 2 && !corner[i]) {  // an interior edge node
      m.x(0, i) += 0.5;
      break;
    }
  homesh::gmsh_adapter::write_model(m);
  gmsh::write(path);
  return path;
}

}  // namespace

TEST_CASE("quality stage: certified validity, views and a report", "[app]") {
  const TempDir dir;
  const std::string out = dir / "quality.msh";
  const auto r =
      run_homesh(geo + "plate_hole.geo -m mesh -m order:p=3 -m quality:measures=Q4,Q6 " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.output.find("validity: 0 invalid of") != std::string::npos);
  REQUIRE(std::regex_search(r.output, std::regex(R"(Q6\s+min 0\.\d+)")));
  homesh::test::GmshSession session;
  gmsh::open(out);
  std::vector<int> views;
  gmsh::view::getTags(views);
  REQUIRE(views.size() == 5);  // minJ/maxJ, Q4 min, Q4, Q6 min, Q6
  std::vector<std::string> names;
  for (int v : views) {
    std::string name;
    gmsh::option::getString("View[" + std::to_string(gmsh::view::getIndex(v)) + "].Name", name);
    names.push_back(name);
  }
  REQUIRE(names == std::vector<std::string>{"minJ/maxJ", "Q4 min", "Q4", "Q6 min", "Q6"});
}

TEST_CASE("an invalid mesh is never written silently", "[app]") {
  const TempDir dir;
  const std::string in = write_invalid_mesh(dir), out = dir / "invalid_output.msh";
  auto r = run_homesh(in + " -m quality " + out);
  INFO(r.output);
  REQUIRE(r.exit_code != 0);
  REQUIRE(std::regex_search(r.output, std::regex(R"(validity: [1-9]\d* invalid of)")));
  REQUIRE(r.output.find("not certified valid (keep them with --keep-invalid)") !=
          std::string::npos);
  REQUIRE_FALSE(std::ifstream(out).good());
  r = run_homesh("--keep-invalid " + in + " " + out);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.output.find("warning: " + out + ": writing") != std::string::npos);
  REQUIRE(std::ifstream(out).good());
}
