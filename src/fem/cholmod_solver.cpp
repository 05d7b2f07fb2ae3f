#include "fem/cholmod_solver.h"

#include "core/error.h"

#ifdef HOMESH_WITH_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace homesh {

#ifdef HOMESH_WITH_CHOLMOD

bool cholmod_available() { return true; }

Eigen::VectorXd cholmod_solve(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& b) {
  Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> solver;
  solver.compute(K);
  if (solver.info() != Eigen::Success)
    throw Error("cholmod_solve: factorisation failed (matrix not positive definite?)");
  Eigen::VectorXd x = solver.solve(b);
  if (solver.info() != Eigen::Success) throw Error("cholmod_solve: solve failed");
  return x;
}

#else

bool cholmod_available() { return false; }

Eigen::VectorXd cholmod_solve(const Eigen::SparseMatrix<double>&, const Eigen::VectorXd&) {
  throw Error("cholmod_solve: homesh was built without CHOLMOD (HOMESH_WITH_CHOLMOD)");
}

#endif

}  // namespace homesh
