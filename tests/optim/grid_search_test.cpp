#include "optim/grid_search.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.h"

using namespace homesh;

TEST_CASE("grid search finds the minimum of a shifted bowl to its last spacing", "[optim]") {
  const Eigen::Vector3d c(0.123, -0.456, 0.789);
  auto f = [&](const Eigen::VectorXd& x) { return (x - c).squaredNorm() + 2.0; };
  const GridSearchResult r =
      grid_search(f, Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1), {21, 3});
  CHECK(r.evaluations == 4 * 21 * 21 * 21);
  CHECK(r.spacing == Approx(0.1 * std::pow(0.2, 3)));
  CHECK((r.x - c).cwiseAbs().maxCoeff() <= r.spacing);
  CHECK(r.value == Approx(f(r.x)));
}

TEST_CASE("grid search keeps the global minimum where a local search would not", "[optim]") {
  // Two wells; the deeper one is far from the box centre.
  auto f = [](const Eigen::VectorXd& x) {
    return -std::exp(-20 * std::pow(x(0) + 0.5, 2)) - 2 * std::exp(-50 * std::pow(x(0) - 0.8, 2));
  };
  const GridSearchResult r =
      grid_search(f, Eigen::VectorXd::Constant(1, -1), Eigen::VectorXd::Ones(1));
  CHECK(r.x(0) == Approx(0.8).margin(r.spacing));
}

TEST_CASE("grid search skips invalid points and rejects bad boxes", "[optim]") {
  auto f = [](const Eigen::VectorXd& x) { return x(0) < 0 ? NAN : (x(0) - 0.3) * (x(0) - 0.3); };
  const GridSearchResult r =
      grid_search(f, Eigen::VectorXd::Constant(1, -1), Eigen::VectorXd::Ones(1));
  CHECK(r.x(0) == Approx(0.3).margin(r.spacing));
  CHECK_THROWS_AS(grid_search(f, Eigen::VectorXd::Ones(1), Eigen::VectorXd::Ones(1)), Error);
  CHECK_THROWS_AS(grid_search(f, Eigen::Vector2d(0, 0), Eigen::VectorXd::Ones(1)), Error);
  CHECK_THROWS_AS(grid_search(f, Eigen::VectorXd::Zero(1), Eigen::VectorXd::Ones(1), {1, 0}),
                  Error);
}
