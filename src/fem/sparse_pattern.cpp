#include "fem/sparse_pattern.h"

#include <algorithm>

namespace homesh {

SparsePattern SparsePattern::of(const Eigen::SparseMatrix<double>& K) {
  SparsePattern p;
  p.outer.assign(K.outerIndexPtr(), K.outerIndexPtr() + K.cols() + 1);
  p.inner.assign(K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros());
  return p;
}

bool SparsePattern::matches(const Eigen::SparseMatrix<double>& K) const {
  const Eigen::Index n = Eigen::Index(outer.size()) - 1;
  return K.rows() == n && K.cols() == n && K.isCompressed() &&
         K.nonZeros() == Eigen::Index(inner.size()) &&
         std::equal(outer.begin(), outer.end(), K.outerIndexPtr()) &&
         std::equal(inner.begin(), inner.end(), K.innerIndexPtr());
}

void SparsePattern::assign_zero(Eigen::SparseMatrix<double>& K) const {
  if (!matches(K)) {
    const Eigen::Index n = Eigen::Index(outer.size()) - 1;
    K.resize(n, n);
    K.resizeNonZeros(Eigen::Index(inner.size()));
    std::copy(outer.begin(), outer.end(), K.outerIndexPtr());
    std::copy(inner.begin(), inner.end(), K.innerIndexPtr());
  }
  std::fill_n(K.valuePtr(), K.nonZeros(), 0.0);
}

}  // namespace homesh
