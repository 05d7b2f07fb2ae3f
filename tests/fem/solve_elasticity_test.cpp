#include "fem/solve_elasticity.h"

#include <catch2/catch.hpp>
#include <string>

#include "core/error.h"
#include "fem_test_support.h"

using namespace homesh;
using namespace homesh::fem_test;

namespace {

// The warped unit square of order p, clamped on its boundary, under gravity.
struct Problem {
  Mesh m;
  DirichletBC bc;
  ElasticityCoefficients c;
};

Problem gravity(int n, int p) {
  Problem pb{unit_square(n, p), {}, {}};
  for (int i : square_boundary(pb.m)) pb.bc.fix(i, Eigen::Vector2d::Zero());
  warp(pb.m, 0.04);
  pb.c.body_force = Eigen::Vector2d(0.0, -1.0);
  return pb;
}

}  // namespace

TEST_CASE("solve_elasticity: CG matches the direct solve and restarts from a guess",
          "[fem][solve_elasticity]") {
  const Problem pb = gravity(4, 4);
  const ElasticitySolution direct = solve_elasticity(pb.m, pb.c, pb.bc);
  ElasticityOptions options;
  options.solver.method = "cg";
  options.solver.preconditioner = "block_jacobi";
  options.solver.tolerance = 1e-12;
  const ElasticitySolution cg = solve_elasticity(pb.m, pb.c, pb.bc, options);
  CHECK(cg.iterations > 10);
  CHECK((cg.u - direct.u).cwiseAbs().maxCoeff() < 1e-10 * direct.u.cwiseAbs().maxCoeff());
  CHECK(solve_elasticity(pb.m, pb.c, pb.bc, options, direct.u).iterations <= 1);
  CHECK_THROWS_AS(solve_elasticity(pb.m, pb.c, pb.bc, options, Eigen::Matrix2Xd::Zero(2, 3)),
                  Error);
}

TEST_CASE("solve_elasticity: per-element E scales the displacement of a force load",
          "[fem][solve_elasticity]") {
  // Doubling E halves u; E = 1 + (e mod 2) lies between the two.
  Problem pb = gravity(3, 3);
  const Eigen::Matrix2Xd u1 = solve_elasticity(pb.m, pb.c, pb.bc).u;
  pb.c.young = per_element(Eigen::VectorXd::Constant(pb.m.num_triangles(), 2.0));
  const Eigen::Matrix2Xd u2 = solve_elasticity(pb.m, pb.c, pb.bc).u;
  CHECK((u2 - 0.5 * u1).cwiseAbs().maxCoeff() < 1e-14);
  Eigen::VectorXd alternating(pb.m.num_triangles());
  for (int e = 0; e < pb.m.num_triangles(); ++e) alternating(e) = 1.0 + e % 2;
  pb.c.young = per_element(alternating);
  const double sag = -solve_elasticity(pb.m, pb.c, pb.bc).u.row(1).minCoeff();
  CHECK(sag < -u1.row(1).minCoeff());
  CHECK(sag > -u2.row(1).minCoeff());
}

TEST_CASE("solve_elasticity: nodes in no triangle stay at rest; invalid input is reported",
          "[fem][solve_elasticity]") {
  Problem pb = gravity(2, 2);
  pb.m.x.conservativeResize(2, pb.m.num_nodes() + 1);
  pb.m.x.col(pb.m.num_nodes() - 1) << 5.0, 5.0;
  const ElasticitySolution s = solve_elasticity(pb.m, pb.c, pb.bc);
  CHECK(s.u.col(pb.m.num_nodes() - 1).norm() == 0.0);
  CHECK(s.u.row(1).minCoeff() < -1e-3);

  Problem bad = gravity(2, 2);
  bad.m.x.col(bad.m.tri(0, 5)).swap(bad.m.x.col(bad.m.tri(1, 5)));  // folds triangle 5
  CHECK_THROWS_WITH(solve_elasticity(bad.m, bad.c, bad.bc),
                    Catch::Contains("triangle") && Catch::Contains("det J"));
  Problem incompressible = gravity(2, 2);
  incompressible.c.poisson = 0.5;
  CHECK_THROWS_AS(solve_elasticity(incompressible.m, incompressible.c, incompressible.bc), Error);
}
