#include "element/lagrange_basis.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "core/error.h"
#include "element/reference_nodes.h"

using namespace homesh;

namespace {

// 2 by n random points in the reference triangle.
Eigen::Matrix2Xd random_points(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Eigen::Matrix2Xd uv(2, n);
  for (int q = 0; q < n; ++q) {
    double u = unit(rng), v = unit(rng);
    if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
    uv.col(q) << u, v;
  }
  return uv;
}

// A random polynomial sum_{a+b<=p} c_ab u^a v^b with c_ab in [-1, 1].
struct Polynomial {
  int p;
  Eigen::MatrixXd c;  // c(a, b), zero for a + b > p

  Polynomial(int p, std::mt19937& rng) : p(p), c(Eigen::MatrixXd::Zero(p + 1, p + 1)) {
    std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
    for (int a = 0; a <= p; ++a)
      for (int b = 0; a + b <= p; ++b) c(a, b) = coefficient(rng);
  }
  // Value, d/du and d/dv at (u, v).
  Eigen::Vector3d operator()(const Eigen::Vector2d& uv) const {
    Eigen::Vector3d f = Eigen::Vector3d::Zero();
    for (int a = 0; a <= p; ++a)
      for (int b = 0; a + b <= p; ++b) {
        f(0) += c(a, b) * std::pow(uv(0), a) * std::pow(uv(1), b);
        if (a > 0) f(1) += c(a, b) * a * std::pow(uv(0), a - 1) * std::pow(uv(1), b);
        if (b > 0) f(2) += c(a, b) * b * std::pow(uv(0), a) * std::pow(uv(1), b - 1);
      }
    return f;
  }
};

}  // namespace

TEST_CASE("LagrangeBasis is a partition of unity with gradients summing to 0",
          "[element][lagrange_basis]") {
  std::mt19937 rng(1);
  for (int p = 1; p <= 10; ++p) {
    INFO("p = " << p);
    const LagrangeBasis basis(p);
    CHECK(basis.order() == p);
    CHECK(basis.size() == (p + 1) * (p + 2) / 2);
    const Eigen::Matrix2Xd uv = random_points(50, rng);
    for (Eigen::Index q = 0; q < uv.cols(); ++q) {
      CHECK(basis.values(uv.col(q)).sum() == Approx(1.0).margin(1e-12));
      const Eigen::Vector2d gradient_sum = basis.gradients(uv.col(q)).rowwise().sum();
      CHECK(gradient_sum.norm() == Approx(0.0).margin(1e-10));
    }
  }
}

TEST_CASE("LagrangeBasis is the Kronecker delta at its nodes", "[element][lagrange_basis]") {
  for (int p = 1; p <= 10; ++p) {
    INFO("p = " << p);
    const LagrangeBasis basis(p);
    CHECK(basis.nodes() == reference_nodes(p));
    const Eigen::MatrixXd N = basis.tabulate_values(basis.nodes());
    const double error =
        (N - Eigen::MatrixXd::Identity(basis.size(), basis.size())).cwiseAbs().maxCoeff();
    CHECK(error < 1e-13);
  }
}

TEST_CASE("LagrangeBasis interpolates degree-p polynomials exactly, values and gradients",
          "[element][lagrange_basis]") {
  std::mt19937 rng(2);
  for (int p = 1; p <= 10; ++p) {
    INFO("p = " << p);
    const LagrangeBasis basis(p);
    const Polynomial f(p, rng);
    Eigen::VectorXd f_nodes(basis.size());
    for (int k = 0; k < basis.size(); ++k) f_nodes(k) = f(basis.nodes().col(k))(0);

    const Eigen::Matrix2Xd uv = random_points(200, rng);
    const Eigen::MatrixXd N = basis.tabulate_values(uv);
    Eigen::MatrixXd dNdu, dNdv;
    basis.tabulate_gradients(uv, dNdu, dNdv);
    double value_error = 0.0, gradient_error = 0.0;
    for (Eigen::Index q = 0; q < uv.cols(); ++q) {
      const Eigen::Vector3d exact = f(uv.col(q));
      value_error = std::max(value_error, std::abs(N.col(q).dot(f_nodes) - exact(0)));
      gradient_error = std::max(gradient_error, std::abs(dNdu.col(q).dot(f_nodes) - exact(1)));
      gradient_error = std::max(gradient_error, std::abs(dNdv.col(q).dot(f_nodes) - exact(2)));
    }
    CHECK(value_error < 1e-12);
    CHECK(gradient_error < 1e-10);
  }
}

TEST_CASE("LagrangeBasis tabulation agrees with pointwise evaluation",
          "[element][lagrange_basis]") {
  std::mt19937 rng(3);
  const LagrangeBasis basis(4);
  const Eigen::Matrix2Xd uv = random_points(20, rng);
  const Eigen::MatrixXd N = basis.tabulate_values(uv);
  Eigen::MatrixXd dNdu, dNdv;
  basis.tabulate_gradients(uv, dNdu, dNdv);
  for (Eigen::Index q = 0; q < uv.cols(); ++q) {
    CHECK(N.col(q) == basis.values(uv.col(q)));
    const Eigen::Matrix2Xd dN = basis.gradients(uv.col(q));
    CHECK(dNdu.col(q) == dN.row(0).transpose());
    CHECK(dNdv.col(q) == dN.row(1).transpose());
  }
}

TEST_CASE("LagrangeBasis gradients match central differences", "[element][lagrange_basis]") {
  std::mt19937 rng(4);
  const double h = 1e-6;
  for (int p : {1, 3, 8}) {
    INFO("p = " << p);
    const LagrangeBasis basis(p);
    const Eigen::Vector2d uv = random_points(1, rng).col(0);
    const Eigen::Vector2d du(h, 0.0), dv(0.0, h);
    const Eigen::Matrix2Xd dN = basis.gradients(uv);
    const Eigen::VectorXd fd_u = (basis.values(uv + du) - basis.values(uv - du)) / (2 * h);
    const Eigen::VectorXd fd_v = (basis.values(uv + dv) - basis.values(uv - dv)) / (2 * h);
    CHECK((dN.row(0).transpose() - fd_u).cwiseAbs().maxCoeff() < 1e-6);
    CHECK((dN.row(1).transpose() - fd_v).cwiseAbs().maxCoeff() < 1e-6);
  }
}

TEST_CASE("LagrangeBasis rejects orders out of range", "[element][lagrange_basis]") {
  CHECK_THROWS_AS(LagrangeBasis(0), Error);
  CHECK_THROWS_WITH(LagrangeBasis(kMaxOrder + 1), Catch::Contains("order 11"));
}
