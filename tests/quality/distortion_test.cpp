// Distortion Theta = 1/Q - 1 (Eq 3.49) and the element distortion function f
// (Eq 3.48).
#include "quality/distortion.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "element/quadrature.h"
#include "measure_test_support.h"
#include "quality/ideal_jacobian.h"

namespace homesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

TEST_CASE("Theta = 1/Q - 1", "[quality]") {
  CHECK(distortion(1.0) == 0.0);
  CHECK(distortion(0.5) == 1.0);
  CHECK(distortion(0.2) == Approx(4.0));
  CHECK(distortion(0.0) == kInf);
  CHECK(distortion(-0.1) == kInf);
}

TEST_CASE("f is 0 for the ideal element, for every measure and order", "[quality]") {
  for (int p : {1, 2, 4}) {
    const ElementSampling rule(p, triangle_quadrature(6));
    for (const Measure& m : measures()) {
      INFO(m.name << " p=" << p);
      CHECK(distortion_function(m, rule, test::equilateral_element(p), 2.0) ==
            Approx(0.0).margin(1e-7));
    }
  }
}

TEST_CASE("f of a straight-sided element is Theta of its constant W, for any r", "[quality]") {
  const Eigen::Vector2d a(0.0, 0.0), b(2.0, 0.3), c(0.6, 0.8);
  const Eigen::Matrix2Xd X = test::straight_element(2, a, b, c);
  Eigen::Matrix2d J;
  J << b - a, c - a;
  const Eigen::Matrix2d W = ideal_jacobian(J);
  const ElementSampling rule(2, triangle_quadrature(4));
  for (const Measure& m : measures()) {
    INFO(m.name);
    const double theta = m.pointwise() ? distortion(m.quality(W)) : 0.0;
    for (double r : {1.5, 2.0, 7.0}) {
      CHECK(distortion_function(m, rule, X, r) == Approx(theta).epsilon(1e-10).margin(1e-7));
    }
  }
}

TEST_CASE("f of a curved element is the r-mean of Theta: positive, growing with r", "[quality]") {
  const Eigen::Matrix2Xd X = test::curved_element(3);
  const ElementSampling rule(3, triangle_quadrature(8));
  for (const Measure& m : measures()) {
    INFO(m.name);
    const double f2 = distortion_function(m, rule, X, 2.0);
    const double f4 = distortion_function(m, rule, X, 4.0);
    const double f16 = distortion_function(m, rule, X, 16.0);
    CHECK(f2 > 0.0);
    CHECK(f2 <= f4 * (1 + 1e-12));
    CHECK(f4 <= f16 * (1 + 1e-12));
    // Bounded by the largest Theta at the rule's points.
    double theta_max = 0.0;
    const ElementQuality q = element_quality(m, rule, X);
    for (int i = 0; i < q.values.size(); ++i)
      theta_max = std::max(theta_max, distortion(q.values[i]));
    CHECK(f16 <= theta_max * (1 + 1e-12));
    // Scaling the element leaves f of the scale-invariant measures unchanged.
    if (m.invariance.scale) {
      CHECK(distortion_function(m, rule, 5.0 * X, 2.0) == Approx(f2).epsilon(1e-10));
    }
  }
}

TEST_CASE("f with the thesis's element-max normalisation ignores constant W", "[quality]") {
  const ElementSampling rule(2, triangle_quadrature(4));
  const Eigen::Matrix2Xd sheared = test::straight_element(2, {0.0, 0.0}, {3.0, 0.0}, {2.5, 1.0});
  for (const char* name : {"Q2", "Q3", "Q4", "Q5", "Q17"}) {
    INFO(name);
    const Measure& m = measure(name);
    CHECK(distortion_function(m, rule, sheared, 2.0) > 0.1);
    CHECK(distortion_function(m, rule, sheared, 2.0, Reference::element_max) ==
          Approx(0.0).margin(1e-7));
  }
}

TEST_CASE("f is infinite for an inverted element and rejects bad input", "[quality]") {
  const ElementSampling rule(2, triangle_quadrature(4));
  Eigen::Matrix2Xd mirrored = test::curved_element(2);
  mirrored.row(1) *= -1.0;
  for (const Measure& m : measures()) {
    INFO(m.name);
    CHECK(distortion_function(m, rule, mirrored, 2.0) == kInf);
    CHECK(distortion_function(m, rule, mirrored, 2.0, Reference::element_max) == kInf);
  }
  const Measure& q8 = measure("Q8");
  const Eigen::Matrix2Xd X = test::curved_element(2);
  CHECK_THROWS_AS(distortion_function(q8, rule, X, 1.0), Error);
  CHECK_THROWS_AS(distortion_function(q8, ElementSampling(2, reference_nodes(3)), X, 2.0), Error);
  CHECK_THROWS_AS(distortion_function(q8, rule, test::curved_element(3), 2.0), Error);
}

}  // namespace homesh
