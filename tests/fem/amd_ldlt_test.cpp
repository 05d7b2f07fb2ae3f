// LDL^T with SuiteSparse's AMD ordering (fem/amd_ldlt.h): the solution of the
// assembled elasticity system agrees with a dense solve, one analysis serves new
// values of the pattern, entries above the diagonal are ignored, and the ordering
// keeps the fill of the factor well below the natural order's.
#include "fem/amd_ldlt.h"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include "core/error.h"
#include "fem/dirichlet.h"
#include "fem_test_support.h"

using namespace homesh;
using namespace homesh::fem_test;

namespace {

// The lower triangle of the eliminated elasticity system of a warped order-p square.
LinearSystem lower_system(int n, int p, double young) {
  LinearSystem sys = sheared_square_system(n, p, young);
  sys.K = Eigen::SparseMatrix<double>(sys.K.triangularView<Eigen::Lower>());
  sys.K.makeCompressed();
  return sys;
}

Eigen::VectorXd dense_solve(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& b) {
  const Eigen::SparseMatrix<double> symmetric = lower.selfadjointView<Eigen::Lower>();
  const Eigen::MatrixXd full = Eigen::MatrixXd(symmetric);
  return full.ldlt().solve(b);
}

}  // namespace

TEST_CASE("amd_ldlt solves the elasticity system as a dense LDL^T does, for new values too",
          "[fem][amd_ldlt]") {
  for (int p : {1, 3}) {
    INFO("p = " << p);
    const LinearSystem a = lower_system(4, p, 1.0);
    AmdLdlt f;
    f.analyze(a.K);
    f.factorize(a.K);
    const Eigen::VectorXd x = f.solve(a.b);
    const Eigen::VectorXd expected = dense_solve(a.K, a.b);
    CHECK((x - expected).norm() < 1e-10 * expected.norm());
    // The same pattern with other values (E x 3): no new analysis needed.
    const LinearSystem b = lower_system(4, p, 3.0);
    REQUIRE(b.K.nonZeros() == a.K.nonZeros());
    f.factorize(b.K);
    const Eigen::VectorXd y = f.solve(b.b);
    CHECK((y - dense_solve(b.K, b.b)).norm() < 1e-10 * y.norm());
    CHECK((y - x).norm() > 1e-3 * x.norm());  // the values did change the answer
  }
}

TEST_CASE("amd_ldlt reads the lower triangle only and rejects what it cannot factorise",
          "[fem][amd_ldlt]") {
  const LinearSystem a = lower_system(3, 2, 1.0);
  // The full symmetric matrix with its upper triangle scaled: ignored.
  Eigen::SparseMatrix<double> full = a.K.selfadjointView<Eigen::Lower>();
  Eigen::SparseMatrix<double> strict_upper = full.triangularView<Eigen::StrictlyUpper>();
  full += strict_upper * 4.0;
  full.makeCompressed();
  AmdLdlt f;
  f.analyze(full);
  f.factorize(full);
  const Eigen::VectorXd expected = dense_solve(a.K, a.b);
  CHECK((f.solve(a.b) - expected).norm() < 1e-10 * expected.norm());
  // Another pattern than the analysed one, a wrong right-hand side, an indefinite matrix.
  CHECK_THROWS_AS(f.factorize(a.K), Error);
  CHECK_THROWS_AS(f.solve(Eigen::VectorXd::Ones(3)), Error);
  Eigen::SparseMatrix<double> indefinite = a.K;
  indefinite.coeffRef(0, 0) = -1.0;
  AmdLdlt g;
  g.analyze(indefinite);
  CHECK_THROWS_AS(g.factorize(indefinite), Error);
  CHECK_FALSE(g.try_factorize(indefinite));  // the same answer without the throw
  CHECK(g.try_factorize(a.K));               // and the same pattern, definite
}

TEST_CASE("amd_ldlt's ordering keeps the factor sparse", "[fem][amd_ldlt]") {
  // On a 12 x 12 order-2 square the natural (node) order is a band a whole row of
  // nodes wide; minimum degree fills far less (seen: 32k against 448k entries of L).
  const LinearSystem a = lower_system(12, 2, 1.0);
  AmdLdlt f;
  f.analyze(a.K);
  f.factorize(a.K);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>
      natural(a.K);
  const Eigen::Index natural_fill = natural.matrixL().nestedExpression().nonZeros();
  INFO("AMD " << f.factor_nonzeros() << ", natural " << natural_fill);
  CHECK(f.factor_nonzeros() < natural_fill / 4);
  const Eigen::VectorXd x = f.solve(a.b);
  const Eigen::VectorXd r = a.b - a.K.selfadjointView<Eigen::Lower>() * x;
  CHECK(r.norm() < 1e-12 * a.b.norm());
}
