#include "optim/praxis.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

using namespace homesh;

TEST_CASE("PRAXIS finds the minimum of a rotated anisotropic quadratic", "[optim]") {
  const Eigen::Vector2d c(0.3, -0.7);
  auto f = [&](const Eigen::VectorXd& x) {
    const double a = x(0) - c(0), b = x(1) - c(1);
    return 10 * (a + b) * (a + b) + (a - b) * (a - b);
  };
  const PraxisResult r = praxis(f, Eigen::Vector2d(2, 2));
  REQUIRE((r.x - c).norm() < 1e-4);
  REQUIRE(r.value < 1e-8);
  REQUIRE(r.evaluations > 2);
}

TEST_CASE("PRAXIS minimises the Rosenbrock function", "[optim]") {
  auto f = [](const Eigen::VectorXd& x) {
    return 100 * std::pow(x(1) - x(0) * x(0), 2) + std::pow(1 - x(0), 2);
  };
  const PraxisResult r = praxis(f, Eigen::Vector2d(-1.2, 1.0), {1e-8, 0.1, 100000});
  REQUIRE(r.x(0) == Approx(1).margin(1e-4));
  REQUIRE(r.x(1) == Approx(1).margin(1e-4));
}

TEST_CASE("PRAXIS is reproducible and records every evaluation", "[optim]") {
  auto f = [](const Eigen::VectorXd& x) { return std::cosh(x(0) - 0.4) + std::pow(x(1) + 0.1, 4); };
  const PraxisResult a = praxis(f, Eigen::Vector2d(1, 1));
  const PraxisResult b = praxis(f, Eigen::Vector2d(1, 1));
  REQUIRE(a.evaluations == b.evaluations);
  REQUIRE((a.x - b.x).norm() == 0.0);
  REQUIRE(static_cast<int>(a.history.size()) == a.evaluations);
  REQUIRE(a.history.front() == Approx(f(Eigen::Vector2d(1, 1))));
  REQUIRE(*std::min_element(a.history.begin(), a.history.end()) == Approx(a.value));
  REQUIRE(a.x(0) == Approx(0.4).margin(1e-4));
}
