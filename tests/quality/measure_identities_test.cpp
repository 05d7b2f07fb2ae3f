// The 2D identities between measures the thesis states (Section 3.7.3) and
// analytic values on straight-sided triangles.
#include <catch2/catch.hpp>
#include <cmath>

#include "measure_test_support.h"
#include "quality/branets_carey_measures.h"
#include "quality/distortion.h"
#include "quality/ideal_jacobian.h"
#include "quality/measure_registry.h"
#include "quality/shape_measures.h"
#include "quality/size_measures.h"

namespace homesh {
namespace {

const std::vector<Eigen::Matrix2d>& identity_samples() {
  static const std::vector<Eigen::Matrix2d> W = test::random_valid_jacobians(2000, 19);
  return W;
}

}  // namespace

TEST_CASE("W is I for the unit equilateral triangle and s R for any equilateral one", "[quality]") {
  const Eigen::Matrix2d J_equilateral = reference_to_ideal_jacobian();
  CHECK((ideal_jacobian(J_equilateral) - Eigen::Matrix2d::Identity()).norm() < 1e-15);
  // Equilateral triangle of side 2.5 rotated by 0.7: J = 2.5 R J_ri.
  const Eigen::Matrix2d R = test::rotation(0.7);
  CHECK((ideal_jacobian(2.5 * R * J_equilateral) - 2.5 * R).norm() < 1e-14);
  // Reference triangle itself: W = inv(J_ri), omega = 2 / sqrt(3).
  CHECK(ideal_jacobian(Eigen::Matrix2d::Identity()).determinant() == Approx(2.0 / std::sqrt(3.0)));
}

TEST_CASE("Q6 = Q7 = Q11 = Q12 in 2D, and raw Q12 is twice raw Q6, Q7, Q11", "[quality]") {
  for (const Eigen::Matrix2d& W : identity_samples()) {
    const double q6 = smoothness_quality(W);
    REQUIRE(aspect_ratio_quality(W) == Approx(q6).epsilon(1e-12));
    REQUIRE(condition_number_quality(W) == Approx(q6).epsilon(1e-12));
    REQUIRE(shape_quality(W) == Approx(q6).epsilon(1e-12));
    // "the half of Q12 is equal to Q6, Q7 and Q11" (Section 3.7.3).
    REQUIRE(0.5 * shape_raw(W) == Approx(smoothness_raw(W)).epsilon(1e-12));
    REQUIRE(0.5 * shape_raw(W) == Approx(aspect_ratio_raw(W)).epsilon(1e-12));
    REQUIRE(0.5 * shape_raw(W) == Approx(condition_number_raw(W)).epsilon(1e-12));
  }
}

TEST_CASE("Q2 = Q5 in 2D", "[quality]") {
  for (const Eigen::Matrix2d& W : identity_samples()) {
    REQUIRE(adjoint_raw(W) == Approx(laplace_raw(W)).epsilon(1e-13));
    REQUIRE(adjoint_quality(W) == Approx(laplace_quality(W)).epsilon(1e-13));
  }
}

TEST_CASE("Q8 and Q16 detect distortion identically: 1/Q16 - 1/Q8 = 1 raw", "[quality]") {
  for (const Eigen::Matrix2d& W : identity_samples()) {
    // "Q16 - Q8 = 1 in two dimensions" (Section 3.7.3), for the inverted forms.
    const double inv16 = 1.0 / metric_condition_number_raw(W);
    REQUIRE(inv16 - 1.0 / oddy_raw(W) == Approx(1.0).margin(1e-13 * inv16));
    // Normalised: Theta8 = 2 Theta16, the same ordering of all elements.
    REQUIRE(
        distortion(oddy_quality(W)) ==
        Approx(2.0 * distortion(metric_condition_number_quality(W))).epsilon(1e-8).margin(1e-12));
  }
}

TEST_CASE("Q9 and Q10 are Q6 and Q7 rescaled by omega^(+-1/3); Q4 = Q17^2", "[quality]") {
  for (const Eigen::Matrix2d& W : identity_samples()) {
    const double cbrt_omega = std::cbrt(W.determinant());
    REQUIRE(nondimensional_smoothness_raw(W) == Approx(smoothness_raw(W) * cbrt_omega));
    REQUIRE(inverse_mean_ratio_raw(W) == Approx(aspect_ratio_raw(W) / cbrt_omega));
    const double q17 = idealised_jacobian_quality(W);
    REQUIRE(equal_volume_quality(W) == Approx(q17 * q17).epsilon(1e-13));
  }
}

TEST_CASE("dilation Q13 is flatter than Q17 around the ideal size; Q14 between Q12, Q13",
          "[quality]") {
  for (const Eigen::Matrix2d& W : identity_samples()) {
    const double q12 = shape_quality(W), q13 = dilation_quality(W);
    REQUIRE(q13 >= idealised_jacobian_quality(W) - 1e-15);
    const double q14 = shape_dilation_quality(W);
    REQUIRE(q14 >= std::min(q12, q13) - 1e-15);
    REQUIRE(q14 <= std::max(q12, q13) + 1e-15);
    REQUIRE(shape_dilation_quality(W, 0.0) == Approx(q12));
    REQUIRE(shape_dilation_quality(W, 1.0) == Approx(q13));
  }
}

TEST_CASE("on straight triangles Q12 is the mean ratio 4 sqrt(3) A / sum l^2", "[quality]") {
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> coord(-3.0, 3.0);
  for (int t = 0; t < 500; ++t) {
    const Eigen::Vector2d a(coord(gen), coord(gen)), b(coord(gen), coord(gen)),
        c(coord(gen), coord(gen));
    Eigen::Matrix2d J;
    J << b - a, c - a;
    const double area = 0.5 * J.determinant();
    if (area < 1e-3) continue;  // keep counter-clockwise, non-degenerate triangles
    const Eigen::Matrix2d W = ideal_jacobian(J);
    const double sum_l2 = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    REQUIRE(shape_quality(W) == Approx(4.0 * std::sqrt(3.0) * area / sum_l2).epsilon(1e-12));
    // omega is the area over that of the unit equilateral triangle.
    REQUIRE(W.determinant() == Approx(area / (std::sqrt(3.0) / 4.0)).epsilon(1e-12));
    // |W|_F^2 is (2/3) sum l^2 (the Laplace energy of the edges, Eq 3.34).
    REQUIRE(laplace_raw(W) == Approx(2.0 / 3.0 * sum_l2).epsilon(1e-12));
  }
}

TEST_CASE("shear at constant area: the thesis's T2 distortion, pointwise", "[quality]") {
  // W = [1 k; 0 1]: the apex of the unit equilateral triangle slid by k along
  // its base. Area measures (Q4, Q13, Q17) cannot see it; shape measures do.
  Eigen::Matrix2d W;
  W << 1.0, 0.4, 0.0, 1.0;
  for (const char* name : {"Q4", "Q13", "Q17"}) CHECK(measure(name).quality(W) == 1.0);
  for (const char* name : {"Q6", "Q7", "Q8", "Q9", "Q10", "Q11", "Q12", "Q14", "Q16"}) {
    INFO(name);
    CHECK(measure(name).quality(W) < 0.99);
  }
  // Q6 analytic: 2 omega / |W|_F^2 = 2 / (2 + k^2).
  CHECK(measure("Q6").quality(W) == Approx(2.0 / 2.16));
}

}  // namespace homesh
