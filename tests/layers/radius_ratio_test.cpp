#include "layers/radius_ratio.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "../layers/layer_test_meshes.h"

using namespace homesh;

namespace {

Eigen::Matrix<double, 2, 3> triangle(double ax, double ay, double bx, double by, double cx,
                                     double cy) {
  Eigen::Matrix<double, 2, 3> X;
  X << ax, bx, cx, ay, by, cy;
  return X;
}

}  // namespace

TEST_CASE("radius ratio (Eq 4.17): 1 for the equilateral, 2 r / R otherwise", "[layers]") {
  CHECK(radius_ratio(triangle(0, 0, 1, 0, 0.5, std::sqrt(3) / 2)) == Approx(1).epsilon(1e-15));
  // Right isosceles: r = (2 - sqrt 2) / 2, R = sqrt 2 / 2, Q = 2 (sqrt 2 - 1).
  CHECK(radius_ratio(triangle(0, 0, 1, 0, 0, 1)) == Approx(2 * (std::sqrt(2) - 1)).epsilon(1e-14));
  // 3-4-5: r = 1, R = 5/2, Q = 0.8.
  CHECK(radius_ratio(triangle(0, 0, 4, 0, 0, 3)) == Approx(0.8).epsilon(1e-14));
  // Right triangle with legs 1 and 10: r = (a + b - c) / 2, R = c / 2.
  const double c = std::sqrt(101.0);
  CHECK(radius_ratio(triangle(0, 0, 10, 0, 0, 1)) == Approx(2 * (11 - c) / c).epsilon(1e-13));
  // Degenerate: collinear, and a repeated point.
  CHECK(radius_ratio(triangle(0, 0, 1, 0, 2, 0)) == Approx(0).margin(1e-15));
  CHECK(radius_ratio(triangle(0, 0, 0, 0, 1, 1)) == 0);
}

TEST_CASE("radius ratio: invariant to motion, scale, node order and orientation", "[layers]") {
  const Eigen::Matrix<double, 2, 3> X = triangle(0.1, 0.2, 1.3, 0.4, 0.5, 0.9);
  const double q = radius_ratio(X);
  REQUIRE(q > 0.3);
  REQUIRE(q < 1);
  const double a = 0.7;
  Eigen::Matrix2d R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  for (double s : {1e-8, 1.0, 1e8}) {
    Eigen::Matrix<double, 2, 3> Y = s * R * X;
    Y.colwise() += s * Eigen::Vector2d(3, -7);
    CHECK(radius_ratio(Y) == Approx(q).epsilon(1e-12));
  }
  Eigen::Matrix<double, 2, 3> Z;
  Z << X.col(1), X.col(0), X.col(2);  // clockwise
  CHECK(radius_ratio(Z) == Approx(q).epsilon(1e-15));
}

TEST_CASE("radius ratios of a mesh: one per triangle", "[layers]") {
  const Mesh m = test::grid_mesh(
      2, 1, 0.5, [](int, int) { return true; }, [](const Eigen::Vector2d&) { return true; });
  const Eigen::VectorXd q = radius_ratios(m);
  REQUIRE(q.size() == 4);
  for (int e = 0; e < 4; ++e) CHECK(q(e) == Approx(2 * (std::sqrt(2) - 1)).epsilon(1e-14));
}
