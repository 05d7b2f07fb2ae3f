#include "element/quad_lagrange_basis.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.h"

using namespace homesh;

TEST_CASE("QuadLagrangeBasis interpolates at its nodes, sums to 1 and reproduces degree p",
          "[element][quad_lagrange_basis]") {
  for (int p = 1; p <= kMaxOrder; ++p) {
    INFO("p = " << p);
    const QuadLagrangeBasis basis(p);
    const Eigen::Matrix2Xd& nodes = basis.nodes();
    for (int k = 0; k < basis.size(); ++k) {
      const Eigen::VectorXd N = basis.values(nodes.col(k));
      Eigen::VectorXd delta = Eigen::VectorXd::Zero(basis.size());
      delta(k) = 1.0;
      CHECK((N - delta).cwiseAbs().maxCoeff() < 1e-10);
    }
    // f = u^p v^p (degree p in each variable) and its gradient at an off-node point.
    const Eigen::Vector2d at(0.3141, 0.7182);
    Eigen::VectorXd f(basis.size());
    for (int k = 0; k < basis.size(); ++k)
      f(k) = std::pow(nodes(0, k), p) * std::pow(nodes(1, k), p);
    const Eigen::VectorXd N = basis.values(at);
    const Eigen::Matrix2Xd dN = basis.gradients(at);
    CHECK(N.sum() == Approx(1.0).margin(1e-10));
    CHECK(dN.row(0).sum() == Approx(0.0).margin(1e-8));
    CHECK(N.dot(f) == Approx(std::pow(at(0) * at(1), p)).margin(1e-10));
    CHECK(dN.row(0).dot(f) == Approx(p * std::pow(at(0), p - 1) * std::pow(at(1), p)).margin(1e-8));
    CHECK(dN.row(1).dot(f) == Approx(p * std::pow(at(0), p) * std::pow(at(1), p - 1)).margin(1e-8));
  }
  CHECK_THROWS_AS(QuadLagrangeBasis(0), Error);
  CHECK_THROWS_AS(QuadLagrangeBasis(kMaxOrder + 1), Error);
}
