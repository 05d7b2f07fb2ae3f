#include "fem/solve_elasticity.h"

#include <string>

#include "core/error.h"

namespace homesh {

ElasticitySolver::ElasticitySolver(const Mesh& m, const DirichletBC& bc,
                                   const ElasticityOptions& options)
    : assembler_(m, bc.dofs, options.assembly), solver_(options.solver) {}

Eigen::VectorXd ElasticitySolver::prescribed(const DirichletBC& bc) const {
  if (bc.dofs.size() != bc.values.size())
    throw Error("apply_dirichlet: " + std::to_string(bc.dofs.size()) + " dofs but " +
                std::to_string(bc.values.size()) + " values");
  Eigen::VectorXd g = Eigen::VectorXd::Zero(assembler_.num_dofs());
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) {
    const int j = bc.dofs[k];
    if (j < 0 || j >= g.size() || !assembler_.fixed()[j])
      throw Error("solve_elasticity: dof " + std::to_string(j) +
                  " was not prescribed when the solver was set up");
    g(j) = bc.values[k];
  }
  return g;
}

ElasticitySolution ElasticitySolver::finish(const Eigen::VectorXd& b,
                                            const Eigen::Matrix2Xd& guess) const {
  const Eigen::Index nodes = assembler_.num_dofs() / 2;
  if (guess.cols() != 0 && guess.cols() != nodes)
    throw Error("solve_elasticity: guess has " + std::to_string(guess.cols()) + " columns for " +
                std::to_string(nodes) + " nodes");
  const Eigen::VectorXd x0 = Eigen::Map<const Eigen::VectorXd>(guess.data(), guess.size());
  LinearSolveResult r = solver_.solve(b, x0);
  assembler_.recover(system_, r.x);
  ElasticitySolution s;
  s.u = Eigen::Map<const Eigen::Matrix2Xd>(r.x.data(), 2, nodes);
  s.iterations = r.iterations;
  s.relative_residual = r.relative_residual;
  return s;
}

ElasticitySolution ElasticitySolver::solve(const Eigen::Matrix2Xd& x,
                                           const ElasticityCoefficients& c, const DirichletBC& bc,
                                           const Eigen::Matrix2Xd& guess) {
  const Eigen::VectorXd g = prescribed(bc);
  assembler_.assemble(x, c, system_);
  solver_.factorize(system_.K);
  ++factorizations_;
  return finish(assembler_.rhs(system_, g), guess);
}

ElasticitySolution ElasticitySolver::resolve(const DirichletBC& bc, const Eigen::Matrix2Xd& guess) {
  if (factorizations_ == 0) throw Error("solve_elasticity: resolve before any solve");
  return finish(assembler_.rhs(system_, prescribed(bc)), guess);
}

ElasticitySolution solve_elasticity(const Mesh& m, const ElasticityCoefficients& c,
                                    const DirichletBC& bc, const ElasticityOptions& options,
                                    const Eigen::Matrix2Xd& guess) {
  ElasticitySolver solver(m, bc, options);
  return solver.solve(m.x, c, bc, guess);
}

}  // namespace homesh
