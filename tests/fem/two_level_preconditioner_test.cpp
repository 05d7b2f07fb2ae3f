#include "fem/two_level_preconditioner.h"

#include <catch2/catch.hpp>
#include <vector>

#include "core/error.h"
#include "fem/conjugate_gradient.h"

using namespace homesh;

namespace {

// The 1D Laplacian (2, -1) on n interior nodes, lower triangle.
Eigen::SparseMatrix<double> laplacian(int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0);
    if (i + 1 < n) t.emplace_back(i + 1, i, -1.0);
  }
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

}  // namespace

TEST_CASE("two_level_preconditioner: CG with a coarse space converges in a bounded number of steps",
          "[fem][two_level_preconditioner]") {
  // Fine 2m + 1 nodes, coarse m (every other node), P linear interpolation,
  // Kc = P^T K P (nested spaces, as an order-2 coarse space is in order p).
  for (const int m : {63, 255}) {
    INFO("coarse nodes " << m);
    const int n = 2 * m + 1;
    const Eigen::SparseMatrix<double> K = laplacian(n);
    std::vector<Eigen::Triplet<double>> t;
    for (int j = 0; j < m; ++j) {
      t.emplace_back(2 * j + 1, j, 1.0);
      t.emplace_back(2 * j, j, 0.5);
      t.emplace_back(2 * j + 2, j, 0.5);
    }
    Eigen::SparseMatrix<double> P(n, m);
    P.setFromTriplets(t.begin(), t.end());
    const Eigen::SparseMatrix<double> full = K.selfadjointView<Eigen::Lower>();
    const Eigen::SparseMatrix<double> Kc =
        Eigen::SparseMatrix<double>(P.transpose() * full * P).triangularView<Eigen::Lower>();
    const Preconditioner jacobi = make_preconditioner("jacobi", K);
    const Preconditioner M = two_level_preconditioner(jacobi, P, Kc);
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
    const ConjugateGradientResult one = conjugate_gradient(K, b, {}, jacobi, 1e-10, 10 * n);
    const ConjugateGradientResult two = conjugate_gradient(K, b, {}, M, 1e-10, 10 * n);
    REQUIRE(one.converged);
    REQUIRE(two.converged);
    CHECK((one.x - two.x).norm() < 1e-8 * one.x.norm());
    // Jacobi CG needs about n / 2 steps; the two-level one a number that does
    // not grow with n (its condition number is bounded).
    CHECK(one.iterations > n / 3);
    CHECK(two.iterations < 20);
    // M^-1 is symmetric: x . M^-1 y = y . M^-1 x.
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
    const Eigen::VectorXd y = Eigen::VectorXd::LinSpaced(n, 3.0, 0.5).array().sin();
    Eigen::VectorXd Mx, My;
    M(x, Mx);
    M(y, My);
    CHECK(y.dot(Mx) == Approx(x.dot(My)).epsilon(1e-12));
  }
  const Eigen::SparseMatrix<double> K = laplacian(5);
  // No coarse unknowns (a region whose lower-order nodes are all held): Jacobi.
  const Preconditioner alone = two_level_preconditioner(
      make_preconditioner("jacobi", K), Eigen::SparseMatrix<double>(5, 0), laplacian(0));
  Eigen::VectorXd z;
  alone(Eigen::VectorXd::Ones(5), z);
  CHECK((z - Eigen::VectorXd::Constant(5, 0.5)).norm() == 0.0);
  CHECK_THROWS_AS(two_level_preconditioner(make_preconditioner("jacobi", K),
                                           Eigen::SparseMatrix<double>(5, 3), laplacian(2)),
                  Error);
}
