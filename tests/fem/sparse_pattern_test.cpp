// A sparse matrix's pattern without its values (fem/sparse_pattern.h): read off a
// matrix, recognised, and given to another with zero values, reusing its storage.
#include "fem/sparse_pattern.h"

#include <catch2/catch.hpp>

using namespace homesh;

TEST_CASE("sparse pattern: of, matches, assign_zero", "[fem][sparse_pattern]") {
  Eigen::SparseMatrix<double> A(3, 3);
  A.insert(0, 0) = 4;
  A.insert(2, 0) = 1;
  A.insert(1, 1) = 5;
  A.insert(2, 2) = 6;
  A.makeCompressed();
  const SparsePattern p = SparsePattern::of(A);
  CHECK(p.outer == std::vector<int>{0, 2, 3, 4});
  CHECK(p.inner == std::vector<int>{0, 2, 1, 2});
  CHECK(p.matches(A));
  Eigen::SparseMatrix<double> B(3, 3);
  B.insert(1, 0) = 1;  // another pattern
  B.makeCompressed();
  CHECK_FALSE(p.matches(B));
  p.assign_zero(B);
  CHECK(p.matches(B));
  CHECK(B.norm() == 0.0);
  // The same pattern again: values zeroed in the storage it has.
  B.coeffRef(2, 0) = 7;
  const double* storage = B.valuePtr();
  p.assign_zero(B);
  CHECK(B.valuePtr() == storage);
  CHECK(B.coeff(2, 0) == 0.0);
  CHECK_FALSE(p.matches(Eigen::SparseMatrix<double>(4, 4)));
}
