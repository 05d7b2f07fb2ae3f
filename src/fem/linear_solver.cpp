#include "fem/linear_solver.h"

#include <Eigen/SparseCholesky>
#include <string>
#include <utility>

#include "core/error.h"
#include "fem/cholmod_solver.h"
#include "fem/conjugate_gradient.h"

namespace homesh {
namespace {

using Matrix = Eigen::SparseMatrix<double>;

LinearSolveResult ldlt(const Matrix& K, const Eigen::VectorXd& b, const LinearSolverOptions&,
                       const Eigen::VectorXd&) {
  const Eigen::SimplicialLDLT<Matrix, Eigen::Lower, Eigen::AMDOrdering<int>> solver(K);
  if (solver.info() != Eigen::Success)
    throw Error("solve_linear_system: ldlt factorisation failed (matrix not positive definite?)");
  return {solver.solve(b), 0, 0.0};
}

LinearSolveResult cholmod(const Matrix& K, const Eigen::VectorXd& b, const LinearSolverOptions&,
                          const Eigen::VectorXd&) {
  return {cholmod_solve(K, b), 0, 0.0};
}

LinearSolveResult cg(const Matrix& K, const Eigen::VectorXd& b,
                     const LinearSolverOptions& options, const Eigen::VectorXd& guess) {
  const int limit = options.max_iterations > 0 ? options.max_iterations : static_cast<int>(b.size());
  ConjugateGradientResult r = conjugate_gradient(
      K, b, guess, make_preconditioner(options.preconditioner, K), options.tolerance, limit);
  if (!r.converged)
    throw Error("solve_linear_system: cg with " + options.preconditioner +
                " did not converge in " + std::to_string(r.iterations) +
                " iterations (relative residual " + std::to_string(r.relative_residual) + ")");
  return {std::move(r.x), r.iterations, r.relative_residual};
}

using Method = LinearSolveResult (*)(const Matrix&, const Eigen::VectorXd&,
                                     const LinearSolverOptions&, const Eigen::VectorXd&);

// The one list of solvers: name and function.
const std::vector<std::pair<std::string, Method>>& registry() {
  static const std::vector<std::pair<std::string, Method>> entries = {
      {"ldlt", ldlt}, {"cholmod", cholmod}, {"cg", cg}};
  return entries;
}

}  // namespace

const std::vector<std::string>& linear_solver_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const auto& entry : registry()) list.push_back(entry.first);
    return list;
  }();
  return names;
}

LinearSolveResult solve_linear_system(const Matrix& K, const Eigen::VectorXd& b,
                                      const LinearSolverOptions& options,
                                      const Eigen::VectorXd& guess) {
  if (K.rows() != K.cols() || K.rows() != b.size())
    throw Error("solve_linear_system: K is " + std::to_string(K.rows()) + " by " +
                std::to_string(K.cols()) + ", b has " + std::to_string(b.size()) + " entries");
  if (guess.size() != 0 && guess.size() != b.size())
    throw Error("solve_linear_system: guess has " + std::to_string(guess.size()) + " entries, b " +
                std::to_string(b.size()));
  for (const auto& [name, method] : registry()) {
    if (name != options.method) continue;
    LinearSolveResult result = method(K, b, options, guess);
    const double b_norm = b.norm();
    result.relative_residual = b_norm > 0.0 ? (b - K * result.x).norm() / b_norm : 0.0;
    return result;
  }
  std::string list;
  for (const std::string& n : linear_solver_names()) list += (list.empty() ? "" : ", ") + n;
  throw Error("solve_linear_system: unknown method '" + options.method + "' (known: " + list + ")");
}

}  // namespace homesh
