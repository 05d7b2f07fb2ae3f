#include "element/square_quadrature.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.h"

using namespace homesh;

namespace {

double moment(const QuadratureRule& rule, int a, int b) {
  double sum = 0.0;
  for (Eigen::Index q = 0; q < rule.weights.size(); ++q)
    sum += rule.weights(q) * std::pow(rule.points(0, q), a) * std::pow(rule.points(1, q), b);
  return sum;
}

}  // namespace

TEST_CASE("square_quadrature integrates u^a v^b exactly for a, b <= degree, degree 0..24",
          "[element][quadrature]") {
  double worst = 0.0;
  for (int degree = 0; degree <= 24; ++degree) {
    INFO("degree = " << degree);
    const QuadratureRule rule = square_quadrature(degree);
    const int n = degree / 2 + 1;
    REQUIRE(rule.points.cols() == n * n);
    REQUIRE(rule.weights.size() == n * n);
    CHECK(rule.weights.minCoeff() > 0.0);
    CHECK(rule.points.minCoeff() > 0.0);
    CHECK(rule.points.maxCoeff() < 1.0);
    for (int a = 0; a <= degree; ++a)
      for (int b = 0; b <= degree; ++b) {
        const double exact = 1.0 / ((a + 1) * (b + 1));
        worst = std::max(worst, std::abs(moment(rule, a, b) - exact) / exact);
      }
  }
  CHECK(worst < 1e-12);
  // Not exact one degree beyond in either variable (odd degree 2n - 1: Gauss
  // misses t^(2n)).
  for (int degree : {1, 5, 11}) {
    const QuadratureRule rule = square_quadrature(degree);
    CHECK(std::abs(moment(rule, degree + 1, 0) - 1.0 / (degree + 2)) > 1e-9);
    CHECK(std::abs(moment(rule, 0, degree + 1) - 1.0 / (degree + 2)) > 1e-9);
  }
  CHECK_THROWS_AS(square_quadrature(-1), Error);
}
