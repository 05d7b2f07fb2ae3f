// The PETSc solve (fem/petsc_solver.h) agrees with CHOLMOD, or says it was not built.
#include "fem/petsc_solver.h"

#include <catch2/catch.hpp>

#include "core/error.h"
#include "fem/dirichlet.h"
#include "fem/linear_solver.h"
#include "fem_test_support.h"

using namespace homesh;
using namespace homesh::fem_test;

namespace {

// A curved order-3 mesh of the warped unit square, clamped below, pushed by a body force.
LinearSystem petsc_test_system() {
  Mesh m = unit_square(4, 3);
  const std::vector<int> boundary = square_boundary(m);
  warp(m, 0.04);
  ElasticityCoefficients c;
  c.young = [](const QuadraturePoint& q) { return 1.0 + 4.0 * q.x(0) * q.x(1); };
  c.poisson = 0.45;
  c.body_force = Eigen::Vector2d(0.3, -1.0);
  LinearSystem sys = assemble_elasticity(m, c);
  DirichletBC bc;
  for (int i : boundary) bc.fix(i, Eigen::Vector2d(0.1 * m.x(1, i), 0.0));
  apply_dirichlet(bc, sys);
  return sys;
}

}  // namespace

TEST_CASE("petsc: CG with Jacobi agrees with CHOLMOD, or says it was not built", "[fem][petsc]") {
  const LinearSystem sys = petsc_test_system();
  LinearSolverOptions o;
  o.method = "petsc";
  o.preconditioner = "jacobi";
  o.tolerance = 1e-12;
  if (!petsc_available()) {
    CHECK_THROWS_WITH(solve_linear_system(sys.K, sys.b, o), Catch::Contains("without PETSc"));
    return;
  }
  const LinearSolveResult direct = solve_linear_system(sys.K, sys.b);
  const LinearSolveResult r = solve_linear_system(sys.K, sys.b, o);
  CHECK(r.iterations > 10);
  CHECK(r.relative_residual < 1e-11);
  CHECK((r.x - direct.x).norm() < 1e-9 * direct.x.norm());
  // The same iterates as homesh's own Jacobi CG (only the sums' rounding differs).
  o.method = "cg";
  const LinearSolveResult own = solve_linear_system(sys.K, sys.b, o);
  CHECK(std::abs(own.iterations - r.iterations) <= 1);
  // From the solution it stops at once; with too few iterations it says so.
  o.method = "petsc";
  CHECK(solve_linear_system(sys.K, sys.b, o, direct.x).iterations <= 1);
  o.max_iterations = 2;
  CHECK_THROWS_WITH(solve_linear_system(sys.K, sys.b, o), Catch::Contains("did not converge"));
}
