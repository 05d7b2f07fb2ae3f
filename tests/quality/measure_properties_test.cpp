// Properties every registered pointwise measure must have (thesis Section 3.7,
// Table 3.7), checked on many random valid W.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>

#include "measure_test_support.h"
#include "quality/measure_registry.h"

namespace homesh {
namespace {

const std::vector<Eigen::Matrix2d>& property_samples() {
  static const std::vector<Eigen::Matrix2d> W = test::random_valid_jacobians(2000);
  return W;
}

bool close(double a, double b) { return std::abs(a - b) <= 1e-10 * std::max(1.0, std::abs(b)); }

// Fraction of the samples on which m.quality changes under `transform` by
// more than rounding (relative 1e-10).
double fraction_changed(
    const Measure& m,
    const std::function<Eigen::Matrix2d(int, const Eigen::Matrix2d&)>& transform) {
  int changed = 0;
  for (size_t i = 0; i < property_samples().size(); ++i) {
    const double q = m.quality(property_samples()[i]);
    if (!close(m.quality(transform(static_cast<int>(i), property_samples()[i])), q)) ++changed;
  }
  return static_cast<double>(changed) / property_samples().size();
}

}  // namespace

TEST_CASE("every pointwise measure is in [0, 1] on valid W and 0 on invalid W", "[quality]") {
  const Eigen::Matrix2d reflect = Eigen::Vector2d(1.0, -1.0).asDiagonal();
  for (const Measure& m : measures()) {
    if (!m.pointwise()) continue;
    INFO(m.name);
    for (const Eigen::Matrix2d& W : property_samples()) {
      const double q = m.quality(W);
      REQUIRE(q > 0.0);
      REQUIRE(q <= 1.0 + 1e-12);
      CHECK(m.quality(W * reflect) == 0.0);
    }
    CHECK(m.quality(Eigen::Matrix2d::Zero()) == 0.0);
    Eigen::Matrix2d singular;
    singular << 1.0, 2.0, 0.5, 1.0;
    CHECK(m.quality(singular) == 0.0);
  }
}

TEST_CASE("every pointwise measure is 1 at the ideal element", "[quality]") {
  for (const Measure& m : measures()) {
    if (!m.pointwise()) continue;
    INFO(m.name);
    CHECK(m.quality(Eigen::Matrix2d::Identity()) == Approx(1.0).epsilon(1e-14));
    for (double angle : {0.3, 1.7, -2.9}) {
      CHECK(m.quality(test::rotation(angle)) == Approx(1.0).epsilon(1e-12));
      if (m.invariance.scale) {
        for (double s : {1e-4, 0.37, 12.0, 1e5}) {
          CHECK(m.quality(s * test::rotation(angle)) == Approx(1.0).epsilon(1e-12));
        }
      }
    }
  }
}

TEST_CASE("quality is the raw Table 3.1 value normalised by its ideal value", "[quality]") {
  // Bounded measures (maximal at the ideal): Q = raw / raw(I). Unbounded
  // (size-sensitive) ones fold the ratio: Q = min(x, 1/x), x = raw / raw(I).
  for (const Measure& m : measures()) {
    if (!m.pointwise()) continue;
    INFO(m.name);
    const double ideal = m.raw(Eigen::Matrix2d::Identity());
    const bool folded = m.normalisation.rfind("min(", 0) == 0;
    for (const Eigen::Matrix2d& W : property_samples()) {
      const double x = m.raw(W) / ideal;
      if (folded) {
        REQUIRE(m.quality(W) == Approx(std::min(x, 1.0 / x)).epsilon(1e-12));
      } else {
        REQUIRE(x <= 1.0 + 1e-12);
        REQUIRE(m.quality(W) == Approx(x).epsilon(1e-12));
      }
    }
  }
}

TEST_CASE("scale and rotation invariance match thesis Table 3.7", "[quality]") {
  const auto table = test::read_reference_table("table_3_7_invariance.csv");
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> log_s(0.5, 7.0), angle(0.1, 2.0 * M_PI - 0.1);
  std::vector<double> scales, angles;
  for (size_t i = 0; i < property_samples().size(); ++i) {
    scales.push_back(std::exp(i % 2 ? log_s(gen) : -log_s(gen)));  // away from 1
    angles.push_back(angle(gen));
  }
  for (const Measure& m : measures()) {
    INFO(m.name);
    REQUIRE(table.count(m.name) == 1);
    const auto& row = table.at(m.name);
    CHECK(m.invariance.label == (row.at("label") == "1"));
    CHECK(m.invariance.scale == (row.at("scale") == "1"));
    CHECK(m.invariance.rotation == (row.at("rotation") == "1"));
    if (!m.pointwise()) continue;  // Q1: see element_quality_test.cpp
    // Invariant: no sample changes. Sensitive: almost every sample changes.
    const double scaled = fraction_changed(
        m, [&](int i, const Eigen::Matrix2d& W) -> Eigen::Matrix2d { return scales[i] * W; });
    const double rotated =
        fraction_changed(m, [&](int i, const Eigen::Matrix2d& W) -> Eigen::Matrix2d {
          return test::rotation(angles[i]) * W;
        });
    INFO("changed by scaling " << scaled << ", by rotation " << rotated);
    CHECK((m.invariance.scale ? scaled == 0.0 : scaled > 0.98));
    CHECK((m.invariance.rotation ? rotated == 0.0 : rotated > 0.98));
  }
  CHECK(table.size() == measures().size());
}

TEST_CASE("relabelling the ideal triangle's corners rotates W on the right", "[quality]") {
  // A cyclic relabelling composes the reference -> physical map with the
  // affine map A of the reference triangle onto itself (u, v) -> (1-u-v, u);
  // W becomes W J_ri A inv(J_ri), and J_ri A inv(J_ri) is the rotation by
  // 120 degrees of the equilateral triangle onto itself. Every measure depends
  // on W only through its singular values and the sign of det W, so it is
  // label-invariant (Table 3.7); element_quality_test.cpp checks whole elements.
  Eigen::Matrix2d A;
  A << -1.0, -1.0, 1.0, 0.0;
  Eigen::Matrix2d J_ri;
  J_ri << 1.0, 0.5, 0.0, std::sqrt(3.0) / 2.0;
  const Eigen::Matrix2d R = J_ri * A * J_ri.inverse();
  CHECK((R - test::rotation(2.0 * M_PI / 3.0)).norm() < 1e-14);
  for (const Measure& m : measures()) {
    if (!m.pointwise()) continue;
    INFO(m.name);
    for (const Eigen::Matrix2d& W : property_samples()) {
      REQUIRE(m.quality(W * R) == Approx(m.quality(W)).epsilon(1e-10));
      REQUIRE(m.quality(W * R * R) == Approx(m.quality(W)).epsilon(1e-10));
    }
  }
}

}  // namespace homesh
