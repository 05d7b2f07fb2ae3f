#include "element/jacobian.h"

#include <catch2/catch.hpp>
#include <random>

#include "element/lagrange_basis.h"
#include "element/reference_nodes.h"

using namespace homesh;

TEST_CASE("jacobian of a straight-sided element is the affine map's matrix",
          "[element][jacobian]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0), unit(0.0, 1.0);
  for (int p = 1; p <= 8; ++p) {
    INFO("p = " << p);
    const LagrangeBasis basis(p);
    // x = A (u, v) + b, with the nodes mapped by the same affine map.
    Eigen::Matrix2d A;
    A << coordinate(rng), coordinate(rng), coordinate(rng), coordinate(rng);
    const Eigen::Vector2d b(coordinate(rng), coordinate(rng));
    const Eigen::Matrix2Xd X = (A * reference_nodes(p)).colwise() + b;
    for (int q = 0; q < 20; ++q) {
      const Eigen::Vector2d uv(unit(rng) / 2.0, unit(rng) / 2.0);
      const Eigen::Matrix2d J = jacobian(X, basis.gradients(uv));
      CHECK((J - A).cwiseAbs().maxCoeff() < 1e-11);
      CHECK(J.determinant() == Approx(A.determinant()).epsilon(1e-10));
    }
  }
}

TEST_CASE("jacobian of a curved quadratic element follows the analytic map",
          "[element][jacobian]") {
  // x = (u, v + u^2): nodes on the quadratic map give J = [[1, 0], [2u, 1]].
  const LagrangeBasis basis(2);
  Eigen::Matrix2Xd X = basis.nodes();
  X.row(1) += X.row(0).array().square().matrix();
  const Eigen::Vector2d uv(0.3, 0.2);
  Eigen::Matrix2d expected;
  expected << 1.0, 0.0, 2.0 * uv(0), 1.0;
  CHECK((jacobian(X, basis.gradients(uv)) - expected).cwiseAbs().maxCoeff() < 1e-14);
}
