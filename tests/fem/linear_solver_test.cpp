// Direct and iterative solvers of the eliminated system agree; Dirichlet
// elimination keeps K symmetric and reproduces the reduced system.
#include "fem/linear_solver.h"

#include <Eigen/Dense>
#include <algorithm>
#include <catch2/catch.hpp>
#include <map>
#include <string>
#include <vector>

#include "core/error.h"
#include "fem/cholmod_solver.h"
#include "fem/dirichlet.h"
#include "fem/preconditioner.h"
#include "fem_test_support.h"

using namespace homesh;
using namespace homesh::fem_test;

namespace {

// A curved order-p mesh of the warped unit square with E varying over a factor
// 5, a body force, and the boundary pushed by a shear.
LinearSystem test_system(int n, int p, DirichletBC* bc_out = nullptr) {
  return sheared_square_system(n, p, 1.0, bc_out);
}

}  // namespace

TEST_CASE("preconditioned CG agrees with the direct solver; ichol needs fewest iterations",
          "[fem][linear_solver]") {
  const LinearSystem sys = test_system(6, 3);
  const LinearSolveResult direct = solve_linear_system(sys.K, sys.b);
  CHECK(direct.iterations == 0);
  CHECK(direct.relative_residual < 1e-13);
  LinearSolverOptions options;
  options.method = "cg";
  options.tolerance = 1e-12;
  std::map<std::string, int> iterations;
  for (const std::string& name : preconditioner_names()) {
    options.preconditioner = name;
    const LinearSolveResult cg = solve_linear_system(sys.K, sys.b, options);
    INFO(name << ": " << cg.iterations << " iterations for " << sys.b.size() << " dofs");
    iterations[name] = cg.iterations;
    CHECK(cg.relative_residual < 1e-11);
    CHECK((cg.x - direct.x).norm() < 1e-9 * direct.x.norm());
    // Restarted from the solution, CG stops at once.
    CHECK(solve_linear_system(sys.K, sys.b, options, direct.x).iterations <= 1);
  }
  // Seen on 2 (19 by 19 nodes) = 722 dofs: jacobi 311, block_jacobi 268, ichol 68.
  CHECK(iterations["ichol"] < iterations["jacobi"] / 3);
  CHECK(iterations["block_jacobi"] < iterations["jacobi"]);
}

TEST_CASE("solve_linear_system rejects unknown names and a non-converging CG",
          "[fem][linear_solver]") {
  const LinearSystem sys = test_system(2, 2);
  LinearSolverOptions options;
  options.method = "lu";
  CHECK_THROWS_AS(solve_linear_system(sys.K, sys.b, options), Error);
  options.method = "cg";
  options.preconditioner = "multigrid";
  CHECK_THROWS_AS(solve_linear_system(sys.K, sys.b, options), Error);
  options.preconditioner = "jacobi";
  options.max_iterations = 2;
  CHECK_THROWS_AS(solve_linear_system(sys.K, sys.b, options), Error);
  CHECK(linear_solver_names() == std::vector<std::string>{"cholmod", "ldlt", "cg", "petsc"});
}

TEST_CASE("cholmod is built in and agrees with ldlt", "[fem][linear_solver]") {
  REQUIRE(cholmod_available());
  const LinearSystem sys = test_system(4, 3);
  LinearSolverOptions options;
  options.method = "cholmod";
  const Eigen::VectorXd x = solve_linear_system(sys.K, sys.b, options).x;
  CHECK((x - solve_linear_system(sys.K, sys.b).x).norm() < 1e-12 * x.norm());
}

TEST_CASE("apply_dirichlet keeps K symmetric and solves the reduced system", "[fem][dirichlet]") {
  Mesh m = unit_square(2, 2);
  warp(m, 0.04);
  ElasticityCoefficients c;
  c.body_force = Eigen::Vector2d(1.0, 0.5);
  const LinearSystem full = assemble_elasticity(m, c);
  DirichletBC bc;
  bc.fix(0, Eigen::Vector2d(0.1, -0.2));
  bc.fix(3, 1, 0.05);
  bc.fix(7, Eigen::Vector2d(0.0, 0.3));
  bc.fix(7, 0, -0.1);  // the last value of a dof wins
  LinearSystem sys = full;
  apply_dirichlet(bc, sys);
  const Eigen::MatrixXd K = sys.K;
  CHECK((K - K.transpose()).cwiseAbs().maxCoeff() == 0.0);

  // Reference: partition into free (f) and fixed (c) dofs, K_ff x_f = b_f - K_fc g.
  const Eigen::MatrixXd A = full.K;
  const std::vector<int> fixed = {0, 1, 7, 14, 15};
  const Eigen::VectorXd g = (Eigen::VectorXd(5) << 0.1, -0.2, 0.05, -0.1, 0.3).finished();
  std::vector<int> free;
  for (int j = 0; j < A.rows(); ++j)
    if (std::find(fixed.begin(), fixed.end(), j) == fixed.end()) free.push_back(j);
  const Eigen::MatrixXd Kff = A(free, free), Kfc = A(free, fixed);
  const Eigen::VectorXd xf = Kff.ldlt().solve(full.b(free) - Kfc * g);

  const Eigen::VectorXd x = solve_linear_system(sys.K, sys.b).x;
  CHECK((x(fixed) - g).cwiseAbs().maxCoeff() < 1e-15);
  CHECK((x(free) - xf).cwiseAbs().maxCoeff() < 1e-13);
  CHECK_THROWS_AS(apply_dirichlet(DirichletBC{{2 * m.num_nodes()}, {0.0}}, sys), Error);
}
