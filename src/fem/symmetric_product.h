#pragma once
// The product of a symmetric sparse matrix stored as its lower triangle with a
// vector, shared among OpenMP threads. The conjugate gradient's one costly
// step: on the 3D elastic analogy at p = 4 (5e7 entries) it is bound by memory
// traffic, and reading each stored entry once for both of its places halves
// that traffic against the full matrix, which also need not be built.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace homesh {

class SymmetricProduct {
 public:
  /// K symmetric, its lower triangle in compressed column storage (entries
  /// above the diagonal, if any, are read as if they were below it: the
  /// caller passes the lower triangle only). K must outlive this object. The
  /// columns are cut into one run per OpenMP thread of about equal entries.
  explicit SymmetricProduct(const Eigen::SparseMatrix<double>& lower);

  /// y = K x. Each thread adds its columns' entries into its own vector
  /// (thread 0 into y), then the vectors are summed by rows.
  void apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;

 private:
  const Eigen::SparseMatrix<double>& k_;
  std::vector<Eigen::Index> start_;               // #runs + 1 column starts
  mutable std::vector<Eigen::VectorXd> partial_;  // runs 1.. (run 0 writes y)
};

}  // namespace homesh
