#include "fem/symmetric_product.h"

#include <omp.h>

#include "core/error.h"

namespace homesh {

SymmetricProduct::SymmetricProduct(const Eigen::SparseMatrix<double>& lower) : k_(lower) {
  if (!lower.isCompressed() || lower.rows() != lower.cols())
    throw Error("SymmetricProduct: the matrix must be square and compressed");
  const Eigen::Index n = lower.cols(), nnz = lower.nonZeros();
  // Small systems are not worth a thread's start.
  const int runs = nnz < 200000 ? 1 : std::max(1, omp_get_max_threads());
  start_.assign(1, 0);
  const int* outer = lower.outerIndexPtr();
  for (int t = 1; t < runs; ++t) {
    const Eigen::Index target = nnz * t / runs;
    Eigen::Index c = start_.back();
    while (c < n && outer[c] < target) ++c;
    start_.push_back(c);
  }
  start_.push_back(n);
  partial_.assign(static_cast<std::size_t>(runs - 1), Eigen::VectorXd(n));
}

void SymmetricProduct::apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  const Eigen::Index n = k_.cols();
  y.resize(n);
  const int runs = static_cast<int>(start_.size()) - 1;
  const int* outer = k_.outerIndexPtr();
  const int* inner = k_.innerIndexPtr();
  const double* value = k_.valuePtr();
#pragma omp parallel num_threads(runs) if (runs > 1)
  {
    // One run per thread if OpenMP gives as many, else some take several.
#pragma omp for schedule(static, 1)
    for (int t = 0; t < runs; ++t) {
      Eigen::VectorXd& out = t == 0 ? y : partial_[static_cast<std::size_t>(t - 1)];
      out.setZero();
      for (Eigen::Index c = start_[static_cast<std::size_t>(t)];
           c < start_[static_cast<std::size_t>(t) + 1]; ++c) {
        const double xc = x[c];
        double sum = 0;
        for (int k = outer[c]; k < outer[c + 1]; ++k) {
          const int r = inner[k];
          out[r] += value[k] * xc;             // K(r, c) x(c)
          if (r != c) sum += value[k] * x[r];  // K(c, r) x(r), the same entry
        }
        out[c] += sum;
      }
    }
#pragma omp for schedule(static)
    for (Eigen::Index i = 0; i < n; ++i)
      for (const Eigen::VectorXd& p : partial_) y[i] += p[i];
  }
}

}  // namespace homesh
