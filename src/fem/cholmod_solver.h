#pragma once
// Adapter to CHOLMOD (SuiteSparse, Chen, Davis, Hager & Rajamanickam 2008), the
// supernodal sparse Cholesky factorisation, through Eigen's CholmodSupport. It is
// compiled in when HOMESH_WITH_CHOLMOD is defined and cholmod is linked; without
// it the library still builds and CholmodFactor reports that it is missing.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

namespace homesh {

/// Whether this build has CHOLMOD.
bool cholmod_available();

/// K = L L^T of symmetric positive definite matrices of one pattern (lower
/// triangle read), CHOLMOD's default (AMD/METIS) fill-reducing ordering.
class CholmodFactor {
 public:
  CholmodFactor();
  ~CholmodFactor();
  CholmodFactor(CholmodFactor&&) noexcept;
  CholmodFactor& operator=(CholmodFactor&&) noexcept;

  /// Ordering and symbolic factorisation of K's pattern.
  void analyze(const Eigen::SparseMatrix<double>& K);
  /// Numeric factorisation of K, whose pattern was analysed last. Throws
  /// homesh::Error if CHOLMOD is not built in or K is not positive definite.
  void factorize(const Eigen::SparseMatrix<double>& K);
  /// x solving K x = b with the last factorisation.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace homesh
