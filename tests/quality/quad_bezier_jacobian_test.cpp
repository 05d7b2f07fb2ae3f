#include "quality/quad_bezier_jacobian.h"

#include <catch2/catch.hpp>
#include <random>

#include "core/error.h"
#include "element/jacobian.h"
#include "element/quad_lagrange_basis.h"
#include "element/quad_reference_nodes.h"
#include "quality/bezier_quad.h"
#include "quality/jacobian_bounds.h"

using namespace homesh;

namespace {

// An order-p quadrilateral: a random convex straight quadrilateral of unit
// size, its non-corner nodes displaced by up to `amplitude` / p.
Eigen::Matrix2Xd curved_quad(int p, double amplitude, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.15, 0.15), unit(-1.0, 1.0);
  const Eigen::Matrix2Xd ref = quad_reference_nodes(p);
  Eigen::Matrix<double, 2, 4> corners;
  corners << 0 + jitter(rng), 1 + jitter(rng), 1 + jitter(rng), 0 + jitter(rng), 0 + jitter(rng),
      0 + jitter(rng), 1 + jitter(rng), 1 + jitter(rng);
  Eigen::Matrix2Xd X(2, ref.cols());
  for (Eigen::Index k = 0; k < ref.cols(); ++k) {
    const double u = ref(0, k), v = ref(1, k);
    X.col(k) = (1 - u) * (1 - v) * corners.col(0) + u * (1 - v) * corners.col(1) +
               u * v * corners.col(2) + (1 - u) * v * corners.col(3);
    if (k >= 4) X.col(k) += amplitude / p * Eigen::Vector2d(unit(rng), unit(rng));
  }
  return X;
}

}  // namespace

TEST_CASE("det J of a quadrilateral from its Bezier coefficients equals det J from the basis",
          "[quality][quad_bezier_jacobian]") {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int p = 1; p <= 6; ++p) {
    INFO("p = " << p);
    const QuadLagrangeBasis basis(p);
    for (int trial = 0; trial < 5; ++trial) {
      const Eigen::Matrix2Xd X = curved_quad(p, 0.3, rng);
      const Eigen::VectorXd c = quad_jacobian_determinant_bezier(X, p);
      REQUIRE(c.size() == 4 * p * p);
      for (int s = 0; s < 10; ++s) {
        const Eigen::Vector2d uv(unit(rng), unit(rng));
        const double direct = jacobian(X, basis.gradients(uv)).determinant();
        const double bezier = quad_bernstein_basis(2 * p - 1, 2 * p - 1, uv).dot(c);
        CHECK(bezier == Approx(direct).margin(1e-12));
      }
    }
  }
  // The unit square has det J = 1 on [0, 1]^2 at every order: all coefficients 1.
  for (int p = 1; p <= 4; ++p)
    CHECK((quad_jacobian_determinant_bezier(quad_reference_nodes(p), p).array() - 1.0)
              .abs()
              .maxCoeff() < 1e-12);
  CHECK_THROWS_AS(quad_jacobian_determinant_bezier(quad_reference_nodes(2), 3), Error);
}

TEST_CASE("quad_bezier_subdivide gives the polynomial on each half-size square",
          "[quality][bezier_quad]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0), coefficient(-1.0, 1.0);
  const Eigen::Vector2d origin[4] = {{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
  for (int d = 0; d <= 7; ++d) {
    Eigen::VectorXd c(quad_bezier_size(d, d));
    for (Eigen::Index i = 0; i < c.size(); ++i) c(i) = coefficient(rng);
    Eigen::MatrixXd sub(c.size(), 4);
    quad_bezier_subdivide(d, c, sub);
    for (int s = 0; s < 4; ++s)
      for (int k = 0; k < 5; ++k) {
        const Eigen::Vector2d uv(unit(rng), unit(rng));
        CHECK(quad_bernstein_basis(d, d, uv).dot(sub.col(s)) ==
              Approx(quad_bernstein_basis(d, d, origin[s] + 0.5 * uv).dot(c)).margin(1e-13));
      }
  }
}

TEST_CASE("quad_jacobian_bounds enclose det J and are tight to the tolerance",
          "[quality][jacobian_bounds]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int p = 1; p <= 4; ++p) {
    INFO("p = " << p);
    const QuadLagrangeBasis basis(p);
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::Matrix2Xd X = curved_quad(p, 0.6, rng);
      const JacobianBounds b = quad_jacobian_bounds(X, p);
      REQUIRE(b.converged);
      double lo = 1e300, hi = -1e300;
      for (int s = 0; s < 400; ++s) {
        const Eigen::Vector2d uv(unit(rng), unit(rng));
        const double J = jacobian(X, basis.gradients(uv)).determinant();
        lo = std::min(lo, J);
        hi = std::max(hi, J);
      }
      CHECK(b.min_lower <= lo);
      CHECK(b.max_upper >= hi);
      CHECK(b.min_upper <= b.min_lower + b.tolerance);
      CHECK(b.max_lower >= b.max_upper - b.tolerance);
      CHECK(b.valid_certified == (b.min_lower > 0));
    }
  }
  // A parallelogram: det J constant (its area on [0, 1]^2), ratio 1.
  Eigen::Matrix2d A;
  A << 2.0, 0.5, 0.0, 1.5;
  const JacobianBounds b = quad_jacobian_bounds(A * quad_reference_nodes(3), 3);
  CHECK(b.min_lower == Approx(3.0));
  CHECK(b.max_upper == Approx(3.0));
  CHECK(scaled_jacobian_ratio(b) == Approx(1.0));
}
