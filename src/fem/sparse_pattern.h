#pragma once
// The pattern of a compressed column sparse matrix (column starts, row indices)
// without its values: kept by those that refill one matrix many times (the
// elasticity assembler, the optimiser's patch Newton steps) or must notice a new
// pattern (LinearSolver's symbolic analysis). An Eigen matrix kept as the pattern
// would allocate and zero values that are never read, and copying it into the
// system would touch them again (on a p = 5 elasticity system of 2.7M entries, a
// third of the assembler's setup).
#include <Eigen/SparseCore>
#include <vector>

namespace homesh {

struct SparsePattern {
  std::vector<int> outer;  ///< #columns + 1 column starts
  std::vector<int> inner;  ///< row indices, column by column

  /// The pattern of K (compressed storage).
  static SparsePattern of(const Eigen::SparseMatrix<double>& K);
  /// Whether K is square, compressed and has exactly this pattern.
  bool matches(const Eigen::SparseMatrix<double>& K) const;
  /// K with this pattern (square) and every value zero; K's storage is reused if it
  /// already has the pattern.
  void assign_zero(Eigen::SparseMatrix<double>& K) const;
};

}  // namespace homesh
