#include "fem/cholmod_solver.h"

#include "core/error.h"

#ifdef HOMESH_WITH_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace homesh {

#ifdef HOMESH_WITH_CHOLMOD

bool cholmod_available() { return true; }

struct CholmodFactor::Impl {
  Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> solver;
};

CholmodFactor::CholmodFactor() : impl_(std::make_unique<Impl>()) {}

void CholmodFactor::analyze(const Eigen::SparseMatrix<double>& K) {
  impl_->solver.analyzePattern(K);
  if (impl_->solver.info() != Eigen::Success) throw Error("cholmod: symbolic analysis failed");
}

void CholmodFactor::factorize(const Eigen::SparseMatrix<double>& K) {
  impl_->solver.factorize(K);
  if (impl_->solver.info() != Eigen::Success)
    throw Error("cholmod: factorisation failed (matrix not positive definite?)");
}

Eigen::VectorXd CholmodFactor::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = impl_->solver.solve(b);
  if (impl_->solver.info() != Eigen::Success) throw Error("cholmod: solve failed");
  return x;
}

#else

bool cholmod_available() { return false; }

struct CholmodFactor::Impl {};

CholmodFactor::CholmodFactor() = default;

void CholmodFactor::analyze(const Eigen::SparseMatrix<double>&) {}

void CholmodFactor::factorize(const Eigen::SparseMatrix<double>&) {
  throw Error("cholmod: homesh was built without CHOLMOD (HOMESH_WITH_CHOLMOD)");
}

Eigen::VectorXd CholmodFactor::solve(const Eigen::VectorXd&) const {
  throw Error("cholmod: homesh was built without CHOLMOD (HOMESH_WITH_CHOLMOD)");
}

#endif

CholmodFactor::~CholmodFactor() = default;
CholmodFactor::CholmodFactor(CholmodFactor&&) noexcept = default;
CholmodFactor& CholmodFactor::operator=(CholmodFactor&&) noexcept = default;

}  // namespace homesh
