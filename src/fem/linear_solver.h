#pragma once
// Solvers of the assembled (and Dirichlet-eliminated) system K x = b of Eq 4.13,
// chosen by name. A LinearSolver keeps what a sequence of systems of one
// sparsity pattern can share: the ordering and symbolic analysis of the direct
// solvers are computed on the first factorisation and reused while the pattern
// stays the same, and one factorisation serves any number of right-hand sides.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <vector>

namespace homesh {

struct LinearSolverOptions {
  /// "cholmod": CHOLMOD's supernodal Cholesky (direct; the default);
  /// "ldlt": Eigen's simplicial LDL^T with SuiteSparse's AMD ordering (fem/amd_ldlt.h;
  ///         direct);
  /// "cg": preconditioned conjugate gradient, as in the thesis.
  std::string method = "cholmod";
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

/// One solver method applied to a sequence of symmetric positive definite
/// matrices. Every matrix is read through its lower triangle (entries above the
/// diagonal, if stored, are ignored), so K may be given in full or lower storage.
class LinearSolver {
 public:
  /// Throws homesh::Error on an unknown method or preconditioner name.
  explicit LinearSolver(LinearSolverOptions options = {});
  ~LinearSolver();
  LinearSolver(LinearSolver&&) noexcept;
  LinearSolver& operator=(LinearSolver&&) noexcept;

  /// Factorises K (direct methods) or builds its preconditioner ("cg"). The
  /// symbolic analysis of a direct method is redone only if K's pattern differs
  /// from the previous one. K must stay alive and unchanged until the next
  /// factorize. Throws homesh::Error if the factorisation fails.
  void factorize(const Eigen::SparseMatrix<double>& K);

  /// x solving K x = b with the last factorised K. `guess` (size of b, or empty
  /// for zero) is the initial iterate of "cg", ignored by direct methods.
  /// Throws homesh::Error if nothing was factorised, on size mismatches, or if
  /// CG does not converge within its iteration limit.
  LinearSolveResult solve(const Eigen::VectorXd& b,
                          const Eigen::VectorXd& guess = Eigen::VectorXd()) const;

  /// Symbolic analyses done so far (each direct factorisation of a new pattern).
  int analyses() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// x solving K x = b, K symmetric positive definite (lower triangle read), by a
/// LinearSolver used once. Throws as LinearSolver.
LinearSolveResult solve_linear_system(const Eigen::SparseMatrix<double>& K,
                                      const Eigen::VectorXd& b,
                                      const LinearSolverOptions& options = {},
                                      const Eigen::VectorXd& guess = Eigen::VectorXd());

}  // namespace homesh
