#include "fem/amd_ldlt.h"

#include <amd.h>

#include <algorithm>
#include <string>

#include "core/error.h"

namespace homesh {

void AmdLdlt::analyze(const Eigen::SparseMatrix<double>& K) {
  const int n = static_cast<int>(K.rows());
  if (K.cols() != n) throw Error("amd_ldlt: the matrix is not square");
  if (!K.isCompressed()) throw Error("amd_ldlt: the matrix must be in compressed storage");
  const int* outer = K.outerIndexPtr();
  const int* inner = K.innerIndexPtr();
  // AMD orders the pattern of K + K^T: the lower triangle is enough.
  std::vector<int> pivot(n);
  if (n > 0) {
    double control[AMD_CONTROL], info[AMD_INFO];
    amd_defaults(control);
    const int status = amd_order(n, outer, inner, pivot.data(), control, info);
    if (status != AMD_OK && status != AMD_OK_BUT_JUMBLED)
      throw Error("amd_ldlt: SuiteSparse AMD failed (status " + std::to_string(status) + ") on a " +
                  std::to_string(n) + " by " + std::to_string(n) + " pattern");
  }
  order_.assign(n, 0);
  for (int k = 0; k < n; ++k) order_[pivot[k]] = k;
  // The lower entries (r >= c) moved to (min, max) of their new positions: counted by
  // column, then placed (Eigen's simplicial factorisation needs no order within a column).
  upper_.resize(n, n);
  int* u_outer = upper_.outerIndexPtr();
  std::fill_n(u_outer, n + 1, 0);
  for (int c = 0; c < n; ++c)
    for (int k = outer[c]; k < outer[c + 1]; ++k)
      if (inner[k] >= c) ++u_outer[std::max(order_[inner[k]], order_[c]) + 1];
  for (int i = 0; i < n; ++i) u_outer[i + 1] += u_outer[i];
  const int m = u_outer[n];
  upper_.resizeNonZeros(m);
  int* u_inner = upper_.innerIndexPtr();
  from_.resize(m);
  std::vector<int> next(u_outer, u_outer + n);
  for (int c = 0; c < n; ++c)
    for (int k = outer[c]; k < outer[c + 1]; ++k) {
      const int r = inner[k];
      if (r < c) continue;
      const int a = order_[r], b = order_[c];
      const int slot = next[std::max(a, b)]++;
      u_inner[slot] = std::min(a, b);
      from_[slot] = k;
    }
  std::fill_n(upper_.valuePtr(), m, 0.0);
  lower_nnz_ = K.nonZeros();
  ldlt_.analyzePattern(upper_);
}

bool AmdLdlt::try_factorize(const Eigen::SparseMatrix<double>& K) {
  if (K.rows() != upper_.rows() || K.cols() != upper_.cols() || K.nonZeros() != lower_nnz_)
    throw Error("amd_ldlt: factorize on a pattern that was not analysed");
  const double* value = K.valuePtr();
  double* u_value = upper_.valuePtr();
  for (std::size_t k = 0; k < from_.size(); ++k) u_value[k] = value[from_[k]];
  ldlt_.factorize(upper_);
  return ldlt_.info() == Eigen::Success && (upper_.rows() == 0 || ldlt_.vectorD().minCoeff() > 0);
}

void AmdLdlt::factorize(const Eigen::SparseMatrix<double>& K) {
  if (!try_factorize(K))
    throw Error("amd_ldlt: factorisation failed (matrix not positive definite)");
}

Eigen::VectorXd AmdLdlt::solve(const Eigen::VectorXd& b) const {
  const Eigen::Index n = upper_.rows();
  if (b.size() != n)
    throw Error("amd_ldlt: b has " + std::to_string(b.size()) + " entries for " +
                std::to_string(n) + " unknowns");
  Eigen::VectorXd permuted(n);
  for (Eigen::Index i = 0; i < n; ++i) permuted(order_[i]) = b(i);
  const Eigen::VectorXd y = ldlt_.solve(permuted);
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i) x(i) = y(order_[i]);
  return x;
}

}  // namespace homesh
