#include "fem/block_lower_assembly.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <random>
#include <vector>

#include "core/error.h"

using namespace homesh;

TEST_CASE("block_lower_assembly adds element matrices as triplets would, in place",
          "[fem][block_lower_assembly]") {
  // 40 elements of 10 nodes each among 60 nodes, a third of them not
  // unknowns (-1), random symmetric element matrices.
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> pick(0, 59);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<int> number(60);
  int nodes = 0;
  for (int& v : number) v = pick(rng) % 3 == 0 ? -1 : nodes++;
  const int k = 10, elements = 40;
  Eigen::MatrixXi unknown(k, elements);
  for (int e = 0; e < elements; ++e)
    for (int a = 0; a < k; ++a) {
      int node;
      bool repeat;
      do {  // distinct nodes within an element
        node = pick(rng);
        repeat = false;
        for (int b = 0; b < a; ++b) repeat = repeat || unknown(b, e) == number[node];
      } while (repeat && number[node] >= 0);
      unknown(a, e) = number[node];
    }
  Eigen::SparseMatrix<double> A = block_lower_pattern(unknown, nodes);
  REQUIRE(A.rows() == 3 * nodes);
  REQUIRE(A.isCompressed());
  std::vector<Eigen::Triplet<double>> triplets;
  for (int e = 0; e < elements; ++e) {
    Eigen::MatrixXd Ke(3 * k, 3 * k);
    for (int i = 0; i < 3 * k; ++i)
      for (int j = 0; j <= i; ++j) Ke(i, j) = Ke(j, i) = value(rng);
    add_block_lower(A, unknown.col(e), Ke);
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b)
        if (unknown(a, e) >= 0 && unknown(b, e) >= 0)
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
              const int row = 3 * unknown(a, e) + i, col = 3 * unknown(b, e) + j;
              if (row >= col) triplets.emplace_back(row, col, Ke(3 * a + i, 3 * b + j));
            }
  }
  Eigen::SparseMatrix<double> expected(3 * nodes, 3 * nodes);
  expected.setFromTriplets(triplets.begin(), triplets.end());
  CHECK((Eigen::MatrixXd(A) - Eigen::MatrixXd(expected)).cwiseAbs().maxCoeff() < 1e-14);
  // Only the lower triangle, each column's rows increasing from its diagonal,
  // and no entry the elements do not couple.
  int coupled = 0;
  for (int c = 0; c < A.cols(); ++c) {
    REQUIRE(A.outerIndexPtr()[c + 1] > A.outerIndexPtr()[c]);
    CHECK(A.innerIndexPtr()[A.outerIndexPtr()[c]] == c);
    for (int p = A.outerIndexPtr()[c] + 1; p < A.outerIndexPtr()[c + 1]; ++p)
      CHECK(A.innerIndexPtr()[p] > A.innerIndexPtr()[p - 1]);
  }
  for (int c = 0; c < expected.cols(); ++c)
    coupled += expected.outerIndexPtr()[c + 1] - expected.outerIndexPtr()[c];
  CHECK(A.nonZeros() == coupled);
}

TEST_CASE("block_rows_pattern gives any rows of the symmetric matrix, bit for bit",
          "[fem][block_lower_assembly]") {
  // Element matrices not symmetric to the last bit (as computed ones may be
  // not): the rows take each entry as the lower triangle does.
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> pick(0, 29);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  const int nodes = 30, k = 4, elements = 25;
  Eigen::MatrixXi unknown(k, elements);
  for (int e = 0; e < elements; ++e) {
    std::vector<int> used;
    for (int a = 0; a < k; ++a) {
      int v;
      do v = pick(rng);
      while (std::find(used.begin(), used.end(), v) != used.end());
      used.push_back(v);
      unknown(a, e) = a == 3 && e % 3 == 0 ? -1 : v;  // some nodes held
    }
  }
  std::vector<Eigen::MatrixXd> Ke;
  for (int e = 0; e < elements; ++e) {
    Eigen::MatrixXd M(3 * k, 3 * k);
    for (int i = 0; i < 3 * k; ++i)
      for (int j = 0; j <= i; ++j) M(i, j) = M(j, i) = value(rng);
    M(1, 0) += 1e-15;  // asymmetric in the last bits
    Ke.push_back(M);
  }
  Eigen::SparseMatrix<double> lower = block_lower_pattern(unknown, nodes);
  for (int e = 0; e < elements; ++e) add_block_lower(lower, unknown.col(e), Ke[e]);
  const Eigen::MatrixXd full = Eigen::SparseMatrix<double>(lower.selfadjointView<Eigen::Lower>());
  // Splits at node boundaries and through a node's three rows.
  for (const auto& [first, count] :
       std::vector<std::pair<int, int>>{{0, 90}, {0, 45}, {45, 45}, {31, 29}, {89, 1}, {7, 0}}) {
    INFO("rows " << first << " + " << count);
    Eigen::SparseMatrix<double, Eigen::RowMajor> rows =
        block_rows_pattern(unknown, nodes, first, count);
    REQUIRE(rows.rows() == count);
    REQUIRE(rows.cols() == 3 * nodes);
    for (int e = 0; e < elements; ++e) add_block_rows(rows, first, unknown.col(e), Ke[e]);
    const Eigen::MatrixXd got(rows);
    CHECK(got == full.middleRows(first, count));
  }
  CHECK_THROWS_AS(block_rows_pattern(unknown, nodes, 80, 11), Error);
}
