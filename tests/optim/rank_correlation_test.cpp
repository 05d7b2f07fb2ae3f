#include "optim/rank_correlation.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.h"

using namespace homesh;

TEST_CASE("ranks: ascending from 1, ties share their mean rank", "[optim]") {
  Eigen::VectorXd v(5);
  v << 3.0, 1.0, 2.0, 1.0, 7.0;
  const Eigen::VectorXd r = ranks(v);
  Eigen::VectorXd expected(5);
  expected << 4.0, 1.5, 3.0, 1.5, 5.0;
  CHECK((r - expected).norm() == 0.0);
}

TEST_CASE("Spearman's rho: 1 for monotone, -1 for reversed, NaN for constant", "[optim]") {
  Eigen::VectorXd a(6), b(6);
  a << 0.1, 0.5, 0.2, 0.9, 0.3, 0.4;
  b = a.array().exp() * 3.0;  // any increasing function
  CHECK(spearman(a, b) == Approx(1.0));
  CHECK(spearman(a, -b) == Approx(-1.0));
  CHECK(std::isnan(spearman(a, Eigen::VectorXd::Constant(6, 2.0))));
  // A known value: one swap in five, rho = 1 - 6 * 2 / (5 * 24) = 0.9.
  Eigen::VectorXd x(5), y(5);
  x << 1, 2, 3, 4, 5;
  y << 1, 3, 2, 4, 5;
  CHECK(spearman(x, y) == Approx(0.9));
  CHECK_THROWS_AS(spearman(x, a), Error);
}
