#pragma once
// Solvers of the assembled (and Dirichlet-eliminated) system K x = b of Eq 4.13,
// chosen by name.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

namespace homesh {

struct LinearSolverOptions {
  /// "ldlt": Eigen's SimplicialLDLT with AMD ordering (direct);
  /// "cholmod": CHOLMOD's supernodal Cholesky (direct; needs a CHOLMOD build);
  /// "cg": preconditioned conjugate gradient, as in the thesis.
  std::string method = "ldlt";
  /// For "cg": a name of preconditioner_names() (fem/preconditioner.h).
  std::string preconditioner = "ichol";
  /// For "cg": stop when ||b - K x|| <= tolerance ||b||.
  double tolerance = 1e-10;
  /// For "cg": iteration limit; 0 means the number of unknowns.
  int max_iterations = 0;
};

struct LinearSolveResult {
  Eigen::VectorXd x;
  int iterations = 0;              // CG iterations, 0 for direct solvers
  double relative_residual = 0.0;  // ||b - K x|| / ||b|| (0 if b = 0)
};

/// The solver names, in the order solve_linear_system accepts them.
const std::vector<std::string>& linear_solver_names();

/// x solving K x = b, K symmetric positive definite in full storage. `guess`
/// (size of b, or empty for zero) is the initial iterate of "cg" and is ignored
/// by direct solvers. Throws homesh::Error on an unknown method, a failed
/// factorisation, or CG not converging within its iteration limit.
LinearSolveResult solve_linear_system(const Eigen::SparseMatrix<double>& K,
                                      const Eigen::VectorXd& b,
                                      const LinearSolverOptions& options = {},
                                      const Eigen::VectorXd& guess = Eigen::VectorXd());

}  // namespace homesh
