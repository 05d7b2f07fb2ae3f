// Tetrahedral meshes through the command line (issue 24), as a user runs them.
#include <gmsh.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>

#include "../support/gmsh_session.h"
#include "../support/run_command.h"
#include "../support/temp_dir.h"
#include "fem/petsc_solver.h"
#include "gmsh/read_volume_model.h"
#include "quality/volume_validity.h"

using homesh::test::geo;
using homesh::test::run_homesh;
using homesh::test::TempDir;

TEST_CASE("curve on a ball in a box: tetrahedra on the sphere, certified valid, groups kept",
          "[app][volume]") {
  const TempDir dir;
  const std::string out = dir / "ball.msh";
  const auto r = run_homesh(geo + "ball_in_box.geo -m curve:p=3 -m quality:measures=Q10 " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("validity: 0 invalid of"));
  CHECK_THAT(r.output, Catch::Contains("tetrahedra"));
  CHECK_THAT(r.output, Catch::Contains("Q10 "));
  homesh::test::GmshSession session;
  gmsh::open(out);
  const homesh::VolumeMesh m = homesh::gmsh_adapter::read_volume_model(out);
  CHECK(m.order == 3);
  CHECK(m.num_tetrahedra() > 1000);
  REQUIRE(m.physicals.size() == 2);
  // Every node on the sphere's surface is on the sphere.
  int on_ball = 0;
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_class[i].dim == 2 && m.x.col(i).norm() < 1.5) {
      ++on_ball;
      CHECK(m.x.col(i).norm() == Approx(1.0).margin(1e-9));
    }
  CHECK(on_ball > 500);
  const homesh::MeshValidity v = homesh::volume_validity(m);
  CHECK(v.invalid == 0);
  CHECK(v.worst > 0.5);
  // The views: the certified minJ/maxJ and Q10's two.
  std::vector<int> views;
  gmsh::view::getTags(views);
  CHECK(views.size() == 3);
}

TEST_CASE("tetrahedra: stages that do not take them, and curve without CAD, refuse by name",
          "[app][volume]") {
  const TempDir dir;
  const std::string mesh = dir / "ball_linear.msh", out = dir / "out.msh";
  REQUIRE(run_homesh(geo + "ball_in_box.geo -m mesh:size_max=1 " + mesh).exit_code == 0);
  auto r = run_homesh(mesh + " -m rotate " + out);
  CHECK(r.exit_code != 0);
  CHECK_THAT(r.output, Catch::Contains("stage 'rotate' does not handle tetrahedra yet (mesh has"));
  CHECK_THAT(r.output, Catch::Contains("'Tetrahedron 4'"));
  r = run_homesh(mesh + " -m curve:p=2 " + out);
  CHECK(r.exit_code != 0);
  CHECK_THAT(r.output, Catch::Contains("has tetrahedra but no CAD"));
  r = run_homesh(mesh + " -m order:p=6 " + out);
  CHECK(r.exit_code != 0);
  CHECK_THAT(r.output, Catch::Contains("tetrahedra of order 1 to 5"));
  // order and quality take the bare mesh.
  r = run_homesh(mesh + " -m order:p=4 -m quality " + out);
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("validity: 0 invalid of"));
}

TEST_CASE("tetrahedra to .vtu: Lagrange tetrahedra with the certified minJ/maxJ", "[app][volume]") {
  const TempDir dir;
  const std::string out = dir / "ball.vtu";
  const auto r = run_homesh(geo + "ball_in_box.geo -m mesh:size_max=1 -m curve:p=2 " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  std::ifstream in(out);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK_THAT(text, Catch::Contains("Name=\"homesh: certified minJ/maxJ\""));
  CHECK_THAT(text, Catch::Contains("NumberOfPoints="));
}

TEST_CASE("tetrahedra: the petsc solve under mpirun -n 2 gives the mesh one process gives",
          "[app][volume][petsc]") {
  const TempDir dir;
  const std::string args = geo + "ball_in_box.geo -m curve:p=2:tet_solver=";
  const auto cg = run_homesh(args + "cg " + dir / "cg.msh");
  REQUIRE(cg.exit_code == 0);
  if (!homesh::petsc_available()) {
    const auto r = run_homesh(args + "petsc " + dir / "one.msh");
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.output, Catch::Contains("without PETSc"));
    return;
  }
  const auto one = run_homesh(args + "petsc " + dir / "one.msh");
  INFO(one.output);
  REQUIRE(one.exit_code == 0);
  // Open MPI refuses root without these; CI runs as root.
  const auto two = homesh::test::run_command(
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -n 2 " +
      homesh::test::homesh_binary + " " + args + "petsc " + dir / "two.msh");
  INFO(two.output);
  REQUIRE(two.exit_code == 0);
  // Rank 0 alone reports (once) and writes.
  std::size_t said = 0;
  for (std::size_t at = 0;
       (at = two.output.find("validity: 0 invalid of", at)) != std::string::npos; ++at)
    ++said;
  CHECK(said == 2);  // the curve stage's line and the summary's, as one process says them
  homesh::test::GmshSession session;
  const auto nodes = [](const std::string& file) {
    gmsh::clear();
    gmsh::open(file);
    return homesh::gmsh_adapter::read_volume_model(file);
  };
  const homesh::VolumeMesh a = nodes(dir / "cg.msh"), b = nodes(dir / "one.msh"),
                           c = nodes(dir / "two.msh");
  REQUIRE(a.x.cols() == b.x.cols());
  REQUIRE(b.x.cols() == c.x.cols());
  CHECK(a.tet == c.tet);
  // Jacobi CG's iterates do not depend on the rows' split: only rounding differs.
  INFO("one against two processes: " << (b.x - c.x).cwiseAbs().maxCoeff());
  CHECK((b.x - c.x).cwiseAbs().maxCoeff() < 1e-12);
  CHECK((a.x - b.x).cwiseAbs().maxCoeff() < 1e-10);  // homesh's own Jacobi CG
}
