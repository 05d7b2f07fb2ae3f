#include "fem/solve_elasticity.h"

#include <string>

#include "core/error.h"

namespace homesh {

ElasticitySolution solve_elasticity(const Mesh& m, const ElasticityCoefficients& c,
                                    const DirichletBC& bc, const ElasticityOptions& options,
                                    const Eigen::Matrix2Xd& guess) {
  LinearSystem sys = assemble_elasticity(m, c, options.assembly);
  apply_dirichlet(bc, sys);
  if (guess.cols() != 0 && guess.cols() != m.num_nodes())
    throw Error("solve_elasticity: guess has " + std::to_string(guess.cols()) + " columns for " +
                std::to_string(m.num_nodes()) + " nodes");
  const Eigen::VectorXd x0 = Eigen::Map<const Eigen::VectorXd>(guess.data(), guess.size());
  LinearSolveResult r = solve_linear_system(sys.K, sys.b, options.solver, x0);
  ElasticitySolution s;
  s.u = Eigen::Map<const Eigen::Matrix2Xd>(r.x.data(), 2, m.num_nodes());
  s.iterations = r.iterations;
  s.relative_residual = r.relative_residual;
  return s;
}

}  // namespace homesh
