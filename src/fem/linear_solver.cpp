#include "fem/linear_solver.h"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <string>
#include <utility>

#include "core/error.h"
#include "fem/amd_ldlt.h"
#include "fem/cholmod_solver.h"
#include "fem/conjugate_gradient.h"
#include "fem/petsc_solver.h"
#include "fem/preconditioner.h"
#include "fem/sparse_pattern.h"

namespace homesh {
namespace {

using Matrix = Eigen::SparseMatrix<double>;

// One method: analyse a pattern, factorise a matrix of it, solve.
struct Backend {
  virtual ~Backend() = default;
  virtual void analyze(const Matrix& K) = 0;
  virtual void factorize(const Matrix& K) = 0;
  virtual LinearSolveResult solve(const Eigen::VectorXd& b, const Eigen::VectorXd& guess) const = 0;
};

struct Ldlt : Backend {
  AmdLdlt factor;
  void analyze(const Matrix& K) override { factor.analyze(K); }
  void factorize(const Matrix& K) override {
    try {
      factor.factorize(K);
    } catch (const Error& e) {
      throw Error(std::string("solve_linear_system: ") + e.what());
    }
  }
  LinearSolveResult solve(const Eigen::VectorXd& b, const Eigen::VectorXd&) const override {
    return {factor.solve(b), 0, 0.0};
  }
};

struct Cholmod : Backend {
  CholmodFactor factor;
  void analyze(const Matrix& K) override { factor.analyze(K); }
  void factorize(const Matrix& K) override {
    try {
      factor.factorize(K);
    } catch (const Error& e) {
      throw Error(std::string("solve_linear_system: ") + e.what());
    }
  }
  LinearSolveResult solve(const Eigen::VectorXd& b, const Eigen::VectorXd&) const override {
    return {factor.solve(b), 0, 0.0};
  }
};

// CG reads the lower triangle as it is (fem/symmetric_product.h): the full
// matrix was twice the memory and, on the 3D elastic analogy at p = 4, twice
// the traffic of each product.
struct Cg : Backend {
  LinearSolverOptions options;
  Matrix lower;
  Preconditioner M;
  explicit Cg(LinearSolverOptions o) : options(std::move(o)) {}
  void analyze(const Matrix&) override {}
  void factorize(const Matrix& K) override {
    lower = K.triangularView<Eigen::Lower>();
    M = make_preconditioner(options.preconditioner, lower);
  }
  LinearSolveResult solve(const Eigen::VectorXd& b, const Eigen::VectorXd& guess) const override {
    const int limit =
        options.max_iterations > 0 ? options.max_iterations : static_cast<int>(b.size());
    ConjugateGradientResult r = conjugate_gradient(lower, b, guess, M, options.tolerance, limit);
    if (!r.converged)
      throw Error("solve_linear_system: cg with " + options.preconditioner +
                  " did not converge in " + std::to_string(r.iterations) +
                  " iterations (relative residual " + std::to_string(r.relative_residual) + ")");
    return {std::move(r.x), r.iterations, r.relative_residual};
  }
};

// PETSc's KSP (fem/petsc_solver.h): the same system on every MPI process.
// Both triangles as rows, once per matrix, from which each process takes its rows.
struct Petsc : Backend {
  LinearSolverOptions options;
  Eigen::SparseMatrix<double, Eigen::RowMajor> full;
  explicit Petsc(LinearSolverOptions o) : options(std::move(o)) {}
  void analyze(const Matrix&) override {}
  void factorize(const Matrix& K) override { full = K.selfadjointView<Eigen::Lower>(); }
  LinearSolveResult solve(const Eigen::VectorXd& b, const Eigen::VectorXd& guess) const override {
    return petsc_solve(full, b, guess, options);
  }
};

using BackendFactory = std::unique_ptr<Backend> (*)(const LinearSolverOptions&);

// The one list of solvers: name and factory.
const std::vector<std::pair<std::string, BackendFactory>>& backend_registry() {
  static const std::vector<std::pair<std::string, BackendFactory>> entries = {
      {"cholmod",
       [](const LinearSolverOptions&) -> std::unique_ptr<Backend> {
         return std::make_unique<Cholmod>();
       }},
      {"ldlt",
       [](const LinearSolverOptions&) -> std::unique_ptr<Backend> {
         return std::make_unique<Ldlt>();
       }},
      {"cg",
       [](const LinearSolverOptions& o) -> std::unique_ptr<Backend> {
         return std::make_unique<Cg>(o);
       }},
      {"petsc", [](const LinearSolverOptions& o) -> std::unique_ptr<Backend> {
         return std::make_unique<Petsc>(o);
       }}};
  return entries;
}

}  // namespace

const std::vector<std::string>& linear_solver_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const auto& entry : backend_registry()) list.push_back(entry.first);
    return list;
  }();
  return names;
}

struct LinearSolver::State {
  std::unique_ptr<Backend> backend;
  const Matrix* K = nullptr;
  SparsePattern analysed;  // the pattern of the last analysis
  int analyses = 0;
};

LinearSolver::LinearSolver(LinearSolverOptions options) : state_(std::make_unique<State>()) {
  for (const auto& [name, factory] : backend_registry())
    if (name == options.method) state_->backend = factory(options);
  if (!state_->backend) {
    std::string list;
    for (const std::string& n : linear_solver_names()) list += (list.empty() ? "" : ", ") + n;
    throw Error("solve_linear_system: unknown method '" + options.method + "' (known: " + list +
                ")");
  }
}

LinearSolver::~LinearSolver() = default;
LinearSolver::LinearSolver(LinearSolver&&) noexcept = default;
LinearSolver& LinearSolver::operator=(LinearSolver&&) noexcept = default;

void LinearSolver::factorize(const Matrix& K) {
  if (K.rows() != K.cols())
    throw Error("solve_linear_system: K is " + std::to_string(K.rows()) + " by " +
                std::to_string(K.cols()));
  if (!K.isCompressed()) throw Error("solve_linear_system: K must be in compressed storage");
  State& s = *state_;
  const bool same = s.analyses > 0 && s.analysed.matches(K);
  s.K = nullptr;
  if (!same) {
    s.backend->analyze(K);
    s.analysed = SparsePattern::of(K);
    ++s.analyses;
  }
  s.backend->factorize(K);
  s.K = &K;
}

LinearSolveResult LinearSolver::solve(const Eigen::VectorXd& b,
                                      const Eigen::VectorXd& guess) const {
  const State& s = *state_;
  if (!s.K) throw Error("solve_linear_system: nothing factorised");
  if (s.K->rows() != b.size())
    throw Error("solve_linear_system: K is " + std::to_string(s.K->rows()) + " by " +
                std::to_string(s.K->cols()) + ", b has " + std::to_string(b.size()) + " entries");
  if (guess.size() != 0 && guess.size() != b.size())
    throw Error("solve_linear_system: guess has " + std::to_string(guess.size()) + " entries, b " +
                std::to_string(b.size()));
  LinearSolveResult result = s.backend->solve(b, guess);
  const double b_norm = b.norm();
  if (b_norm > 0.0) {
    Eigen::VectorXd r = b;
    r.noalias() -= s.K->selfadjointView<Eigen::Lower>() * result.x;
    result.relative_residual = r.norm() / b_norm;
  }
  return result;
}

int LinearSolver::analyses() const { return state_->analyses; }

LinearSolveResult solve_linear_system(const Matrix& K, const Eigen::VectorXd& b,
                                      const LinearSolverOptions& options,
                                      const Eigen::VectorXd& guess) {
  LinearSolver solver(options);
  if (K.rows() != b.size())
    throw Error("solve_linear_system: K is " + std::to_string(K.rows()) + " by " +
                std::to_string(K.cols()) + ", b has " + std::to_string(b.size()) + " entries");
  if (K.isCompressed()) {
    solver.factorize(K);
    return solver.solve(b, guess);
  }
  const Matrix compressed = K;
  solver.factorize(compressed);
  return solver.solve(b, guess);
}

}  // namespace homesh
