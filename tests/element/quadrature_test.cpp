#include "element/quadrature.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <utility>

#include "core/error.h"
#include "element/gauss_jacobi.h"

using namespace homesh;

namespace {

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

}  // namespace

TEST_CASE("triangle_quadrature integrates u^a v^b exactly for a + b <= degree, degree 0..30",
          "[element][quadrature]") {
  double worst = 0.0;
  for (int degree = 0; degree <= 30; ++degree) {
    INFO("degree = " << degree);
    const QuadratureRule rule = triangle_quadrature(degree);
    REQUIRE(rule.points.cols() == rule.weights.size());
    CHECK(rule.weights.minCoeff() > 0.0);
    CHECK(rule.points.minCoeff() > 0.0);
    CHECK(rule.points.colwise().sum().maxCoeff() < 1.0);
    for (int a = 0; a <= degree; ++a) {
      for (int b = 0; a + b <= degree; ++b) {
        const double exact = factorial(a) * factorial(b) / factorial(a + b + 2);
        double sum = 0.0;
        for (Eigen::Index q = 0; q < rule.weights.size(); ++q)
          sum += rule.weights(q) * std::pow(rule.points(0, q), a) * std::pow(rule.points(1, q), b);
        worst = std::max(worst, std::abs(sum - exact) / exact);
      }
    }
  }
  CHECK(worst < 1e-12);
}

TEST_CASE("triangle_quadrature is not exact one degree beyond", "[element][quadrature]") {
  // n = degree / 2 + 1 points per direction: for odd degree 2n - 1 the rule
  // misses v^(2n) (a Gauss rule is never exact to 2n).
  for (int degree : {1, 5, 11}) {
    const QuadratureRule rule = triangle_quadrature(degree);
    const int b = degree + 1;
    const double exact = factorial(b) / factorial(b + 2);
    double sum = 0.0;
    for (Eigen::Index q = 0; q < rule.weights.size(); ++q)
      sum += rule.weights(q) * std::pow(rule.points(1, q), b);
    CHECK(std::abs(sum - exact) > 1e-6 * exact);
  }
}

TEST_CASE("tetrahedron_quadrature integrates u^a v^b w^c exactly to its degree, 0..16, not beyond",
          "[element][quadrature]") {
  double worst = 0.0;
  for (int degree = 0; degree <= 16; ++degree) {
    INFO("degree = " << degree);
    const TetQuadratureRule rule = tetrahedron_quadrature(degree);
    REQUIRE(rule.points.cols() == rule.weights.size());
    CHECK(rule.weights.minCoeff() > 0.0);
    CHECK(rule.points.minCoeff() > 0.0);
    CHECK(rule.points.colwise().sum().maxCoeff() < 1.0);
    const auto integral = [&](int a, int b, int c) {
      double sum = 0.0;
      for (Eigen::Index q = 0; q < rule.weights.size(); ++q)
        sum += rule.weights(q) * std::pow(rule.points(0, q), a) * std::pow(rule.points(1, q), b) *
               std::pow(rule.points(2, q), c);
      return sum;
    };
    for (int a = 0; a <= degree; ++a)
      for (int b = 0; a + b <= degree; ++b)
        for (int c = 0; a + b + c <= degree; ++c) {
          const double exact =
              factorial(a) * factorial(b) * factorial(c) / factorial(a + b + c + 3);
          worst = std::max(worst, std::abs(integral(a, b, c) - exact) / exact);
        }
    if (degree % 2 == 1) {  // w^(degree+1) is beyond n Gauss points in t
      const double exact = factorial(degree + 1) * 2.0 / factorial(degree + 4);
      CHECK(std::abs(integral(0, 0, degree + 1) - exact) > 1e-8 * exact);
    }
  }
  CHECK(worst < 1e-12);
}

TEST_CASE("line_quadrature is Gauss-Legendre on [0, 1] exact to its degree, 0..30",
          "[element][quadrature]") {
  for (int degree = 0; degree <= 30; ++degree) {
    INFO("degree = " << degree);
    const LineQuadratureRule rule = line_quadrature(degree);
    CHECK(rule.points.size() == degree / 2 + 1);
    CHECK(rule.weights.minCoeff() > 0.0);
    CHECK(rule.points.minCoeff() > 0.0);
    CHECK(rule.points.maxCoeff() < 1.0);
    for (int k = 0; k <= degree; ++k)
      CHECK(rule.weights.dot(rule.points.array().pow(k).matrix()) ==
            Approx(1.0 / (k + 1)).epsilon(1e-13));
  }
  // The 2-point rule: points (1 -+ 1/sqrt(3)) / 2, weights 1/2.
  const LineQuadratureRule two = line_quadrature(3);
  CHECK(two.points(0) == Approx((1.0 - 1.0 / std::sqrt(3.0)) / 2.0).epsilon(1e-15));
  CHECK(two.points(1) == Approx((1.0 + 1.0 / std::sqrt(3.0)) / 2.0).epsilon(1e-15));
  CHECK(two.weights(0) == Approx(0.5).epsilon(1e-15));
}

TEST_CASE("gauss_jacobi integrates against (1-t)^alpha t^beta exactly to degree 2n-1",
          "[element][quadrature]") {
  // int_0^1 t^k (1-t)^alpha t^beta dt = B(alpha + 1, beta + k + 1).
  auto beta_function = [](double x, double y) {
    return std::exp(std::lgamma(x) + std::lgamma(y) - std::lgamma(x + y));
  };
  const std::pair<double, double> exponents[] = {{1.0, 0.0}, {2.0, 0.0}, {0.5, -0.5}, {3.0, 1.5}};
  for (const auto& [alpha, beta] : exponents) {
    for (int n = 1; n <= 12; ++n) {
      INFO("alpha = " << alpha << ", beta = " << beta << ", n = " << n);
      const LineQuadratureRule rule = gauss_jacobi(n, alpha, beta);
      CHECK(rule.weights.minCoeff() > 0.0);
      for (int k = 0; k <= 2 * n - 1; ++k)
        CHECK(rule.weights.dot(rule.points.array().pow(k).matrix()) ==
              Approx(beta_function(alpha + 1, beta + k + 1)).epsilon(1e-12));
    }
  }
}

TEST_CASE("quadrature rejects negative degrees and point counts", "[element][quadrature]") {
  CHECK_THROWS_AS(triangle_quadrature(-1), Error);
  CHECK_THROWS_AS(tetrahedron_quadrature(-1), Error);
  CHECK_THROWS_AS(line_quadrature(-2), Error);
  CHECK_THROWS_AS(gauss_jacobi(0, 0.0, 0.0), Error);
  CHECK_THROWS_AS(gauss_jacobi(3, -1.0, 0.0), Error);
}
