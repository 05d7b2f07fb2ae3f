// The curve stage run as a user does: boundary nodes on the CAD, certified valid.
#include <gmsh.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <regex>

#include "gmsh/read_model.h"
#include "../support/gmsh_session.h"
#include "../support/run_command.h"

using homesh::test::run_homesh;

namespace {
const std::string geo = std::string(HOMESH_SOURCE_DIR) + "/geo/";
}

TEST_CASE("curve: the plate's hole nodes lie on the circle, every element valid", "[app]") {
  for (int p : {2, 4}) {
    CAPTURE(p);
    const std::string out = "/tmp/homesh_curve_plate.msh";
    const auto r = run_homesh(geo + "plate_hole.geo -m mesh -m curve:p=" + std::to_string(p) +
                              ":formulation=heat_q17 -m quality " + out);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    REQUIRE(r.output.find("validity: 0 invalid of") != std::string::npos);
    homesh::test::GmshSession session;
    gmsh::open(out);
    const homesh::Mesh m = homesh::gmsh_adapter::read_model(out);
    REQUIRE(m.order == p);
    double worst = 0;
    int on_hole = 0;
    for (int k = 0; k < m.num_lines(); ++k) {
      const double r0 = m.x.col(m.line(0, k)).norm();
      if (std::abs(r0 - 0.5) > 1e-9) continue;
      for (int j = 0; j <= p; ++j, ++on_hole)
        worst = std::max(worst, std::abs(m.x.col(m.line(j, k)).norm() - 0.5));
    }
    REQUIRE(on_hole > 0);
    REQUIRE(worst < 1e-12);
    std::remove(out.c_str());
    std::remove((out + ".opt").c_str());
  }
}

TEST_CASE("curve: NACA-7526 at order 4, valid, with a bad option refused", "[app]") {
  const std::string out = "/tmp/homesh_curve_naca.msh";
  auto r = run_homesh(geo + "naca.geo -m mesh -m curve:p=4 " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  std::smatch m;
  REQUIRE(std::regex_search(r.output, m, std::regex(R"(validity: 0 invalid of \d+ triangles.*worst minJ/maxJ (\d\.\d+))")));
  REQUIRE(std::stod(m[1]) > 0.9);
  r = run_homesh(geo + "naca.geo -m mesh -m curve:p=4:formulation=magic " + out);
  REQUIRE(r.exit_code != 0);
  REQUIRE(r.output.find("unknown formulation 'magic'") != std::string::npos);
  r = run_homesh(geo + "naca.geo -m mesh -m curve:p=4:nu=0.5 " + out);
  REQUIRE(r.exit_code != 0);
  REQUIRE(r.output.find("nu must be in (-1, 0.5)") != std::string::npos);
  std::remove(out.c_str());
  std::remove((out + ".opt").c_str());
}
