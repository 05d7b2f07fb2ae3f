// Measures over whole elements: consistency with the pointwise kernels, Q1,
// label invariance under relabelling, the thesis's element-max normalisation.
#include "quality/element_quality.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.h"
#include "element/reference_nodes.h"
#include "measure_test_support.h"
#include "quality/ideal_jacobian.h"
#include "quality/jacobian_variation.h"

namespace homesh {
namespace {

// ~200 points of the reference triangle (thesis Section 3.6): the order-18
// lattice, a set the cyclic corner permutation maps onto itself.
const Eigen::Matrix2Xd& lattice() {
  static const Eigen::Matrix2Xd uv = reference_nodes(18);
  return uv;
}

Eigen::VectorXd sorted(Eigen::VectorXd v) {
  std::sort(v.data(), v.data() + v.size());
  return v;
}

}  // namespace

TEST_CASE("on a straight-sided element every point has the quality of its W", "[quality]") {
  const Eigen::Vector2d a(0.2, 0.1), b(1.7, 0.4), c(0.5, 0.9);
  const Eigen::Matrix2Xd X = test::straight_element(3, a, b, c);
  Eigen::Matrix2d J;
  J << b - a, c - a;
  const Eigen::Matrix2d W = ideal_jacobian(J);
  for (const Measure& m : measures()) {
    INFO(m.name);
    const ElementQuality q = element_quality(m, X, 3, lattice());
    REQUIRE(q.values.size() == lattice().cols());
    const double expected = m.pointwise() ? m.quality(W) : 1.0;
    CHECK(q.min == Approx(expected).epsilon(1e-10));
    CHECK((q.values.array() - expected).abs().maxCoeff() < 1e-10);
  }
}

TEST_CASE("Q1 is min J / max J, one value over the element", "[quality]") {
  const Eigen::Matrix2Xd X = test::curved_element(2);
  const ElementSampling s(2, lattice());
  double lo = 1e300, hi = -1e300;
  for (int k = 0; k < s.size(); ++k) {
    const double J = s.jacobian(X, k).determinant();
    lo = std::min(lo, J);
    hi = std::max(hi, J);
  }
  REQUIRE(lo > 0.0);
  CHECK(jacobian_variation(s, X) == Approx(lo / hi));
  CHECK(jacobian_variation(s, X) < 0.95);
  const ElementQuality q = element_quality(measure("Q1"), s, X);
  CHECK((q.values.array() == q.min).all());
  // A mid-node pushed across the opposite edge's neighbourhood inverts J.
  Eigen::Matrix2Xd folded = X;
  folded.col(3) = Eigen::Vector2d(0.6, 1.4);
  CHECK(jacobian_variation(s, folded) == 0.0);
}

TEST_CASE("relabelling the corners leaves every element measure unchanged", "[quality]") {
  for (int p : {2, 3, 4}) {
    const Eigen::Matrix2Xd X = test::curved_element(p);
    const Eigen::Matrix2Xd Y = test::relabel_cyclic(X, p);
    const Eigen::Matrix2Xd Z = test::relabel_cyclic(Y, p);
    CHECK((test::relabel_cyclic(Z, p) - X).norm() == 0.0);  // three turns: identity
    const ElementSampling s(p, lattice());
    REQUIRE(jacobian_variation(s, X) > 0.0);  // valid
    for (const Measure& m : measures()) {
      INFO(m.name << " p=" << p);
      const ElementQuality qx = element_quality(m, s, X);
      const ElementQuality qy = element_quality(m, s, Y);
      const ElementQuality qz = element_quality(m, s, Z);
      CHECK(qx.min < 1.0);
      CHECK(qy.min == Approx(qx.min).epsilon(1e-10));
      CHECK(qz.min == Approx(qx.min).epsilon(1e-10));
      CHECK((sorted(qy.values) - sorted(qx.values)).cwiseAbs().maxCoeff() < 1e-10);
      CHECK((sorted(qz.values) - sorted(qx.values)).cwiseAbs().maxCoeff() < 1e-10);
    }
  }
}

TEST_CASE("element measures follow Table 3.7 under scaling and rotating the nodes", "[quality]") {
  const Eigen::Matrix2Xd X = test::curved_element(2);
  const Eigen::Matrix2Xd moved = 3.7 * test::rotation(1.1) * X;
  const ElementSampling s(2, lattice());
  for (const Measure& m : measures()) {
    INFO(m.name);
    const Eigen::VectorXd q = element_quality(m, s, X).values;
    const double change = (element_quality(m, s, moved).values - q).cwiseAbs().maxCoeff();
    // Rotation never changes anything (all invariant); scaling changes exactly
    // the scale-sensitive measures.
    CHECK((m.invariance.scale ? change < 1e-10 : change > 1e-3));
    const Eigen::Matrix2Xd rotated = test::rotation(-2.3) * X;
    CHECK((element_quality(m, s, rotated).values - q).cwiseAbs().maxCoeff() < 1e-10);
  }
}

TEST_CASE("thesis Table 3.2, columns T1 and T2, with the thesis's normalisation", "[quality]") {
  // T1 is the ideal element; T2 slides its apex parallel to the base (constant
  // W, a pure shear at the ideal area). With Q / Qmax over the element for
  // Q2-Q5, Q17 (Reference::element_max) the detections match Table 3.2.
  const auto table = test::read_reference_table("table_3_2_distortion_representation.csv");
  const double h = std::sqrt(3.0) / 2.0;
  const Eigen::Matrix2Xd T1 = test::equilateral_element(2);
  const Eigen::Matrix2Xd T2 = test::straight_element(2, {0.0, 0.0}, {1.0, 0.0}, {0.85, h});
  const ElementSampling s(2, lattice());
  for (const Measure& m : measures()) {
    INFO(m.name);
    REQUIRE(table.count(m.name) == 1);
    CHECK(element_quality(m, s, T1, Reference::element_max).min == Approx(1.0).epsilon(1e-12));
    CHECK(element_quality(m, s, T1).min == Approx(1.0).epsilon(1e-12));
    const bool detected = element_quality(m, s, T2, Reference::element_max).min < 1.0 - 1e-9;
    CHECK(detected == (table.at(m.name).at("T2") == "1"));
  }
}

TEST_CASE("Reference::element_max divides the raw value by its element maximum", "[quality]") {
  const Eigen::Matrix2Xd X = test::curved_element(3);
  const ElementSampling s(3, lattice());
  for (const Measure& m : measures()) {
    INFO(m.name);
    const ElementQuality q = element_quality(m, s, X, Reference::element_max);
    if (!m.thesis_max_normalised) {
      CHECK((q.values - element_quality(m, s, X).values).norm() == 0.0);
      continue;
    }
    CHECK(q.values.maxCoeff() == 1.0);
    double max_raw = 0.0;
    for (int k = 0; k < s.size(); ++k) {
      max_raw = std::max(max_raw, m.raw(ideal_jacobian(s.jacobian(X, k))));
    }
    const Eigen::Matrix2d W0 = ideal_jacobian(s.jacobian(X, 0));
    CHECK(q.values[0] == Approx(m.raw(W0) / max_raw));
    // Scale-invariant over the element, unlike the pointwise normalisation.
    CHECK((element_quality(m, s, 0.01 * X, Reference::element_max).values - q.values).norm() <
          1e-10);
  }
}

TEST_CASE("element evaluation checks the number of nodes", "[quality]") {
  const ElementSampling s(2, lattice());
  CHECK(s.node_count() == 6);
  CHECK_THROWS_AS(element_quality(measure("Q7"), s, test::curved_element(3)), Error);
}

}  // namespace homesh
