// The PETSc solve (fem/petsc_solver.h) agrees with CHOLMOD, or says it was not built.
#include "fem/petsc_solver.h"

#include <catch2/catch.hpp>

#include "core/error.h"
#include "fem/linear_solver.h"
#include "fem_test_support.h"

using namespace homesh;
using namespace homesh::fem_test;

TEST_CASE("petsc: CG with Jacobi agrees with CHOLMOD, or says it was not built", "[fem][petsc]") {
  const LinearSystem sys = sheared_square_system(4, 3);
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
