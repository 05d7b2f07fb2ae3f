#include "fem/dirichlet.h"

#include <string>

#include "core/error.h"

namespace homesh {

void DirichletBC::fix(int node, const Eigen::Vector2d& u) {
  fix(node, 0, u(0));
  fix(node, 1, u(1));
}

void DirichletBC::fix(int node, int component, double value) {
  dofs.push_back(2 * node + component);
  values.push_back(value);
}

void apply_dirichlet(const DirichletBC& bc, LinearSystem& sys) {
  const Eigen::Index n = sys.K.rows();
  if (bc.dofs.size() != bc.values.size())
    throw Error("apply_dirichlet: " + std::to_string(bc.dofs.size()) + " dofs but " +
                std::to_string(bc.values.size()) + " values");
  std::vector<char> fixed(n, 0);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
  for (size_t k = 0; k < bc.dofs.size(); ++k) {
    const int j = bc.dofs[k];
    if (j < 0 || j >= n)
      throw Error("apply_dirichlet: dof " + std::to_string(j) + " out of range 0.." +
                  std::to_string(n - 1));
    fixed[j] = 1;
    g(j) = bc.values[k];
  }
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(n);
  for (Eigen::Index j = 0; j < sys.K.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(sys.K, j); it; ++it) {
      const Eigen::Index i = it.row();
      if (i == j) {
        diagonal(j) = it.value();
      } else if (fixed[i] || fixed[j]) {
        if (fixed[j] && !fixed[i]) sys.b(i) -= it.value() * g(j);
        it.valueRef() = 0.0;
      }
    }
  }
  for (Eigen::Index j = 0; j < n; ++j) {
    if (!fixed[j]) continue;
    if (diagonal(j) == 0.0) {
      diagonal(j) = 1.0;
      sys.K.coeffRef(j, j) = 1.0;
    }
    sys.b(j) = diagonal(j) * g(j);
  }
  sys.K.prune([](Eigen::Index i, Eigen::Index j, double v) { return i == j || v != 0.0; });
}

}  // namespace homesh
