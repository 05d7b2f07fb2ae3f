#include "quality/bezier_tetrahedron.h"

#include <catch2/catch.hpp>
#include <random>

#include "core/error.h"

using namespace homesh;

namespace {

Eigen::Vector3d random_point(std::mt19937& rng) {
  std::uniform_real_distribution<double> U(0, 1);
  for (;;) {
    const Eigen::Vector3d y(U(rng), U(rng), U(rng));
    if (y.sum() <= 1) return y;
  }
}

}  // namespace

TEST_CASE("tetrahedron Bernstein coefficients: from lattice values and back, corners exact",
          "[quality][bezier]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int d = 0; d <= kMaxTetBezierDegree; ++d) {
    INFO("d = " << d);
    const int n = tetrahedron_bezier_size(d);
    const Eigen::Matrix3Xi idx = tetrahedron_bezier_indices(d);
    REQUIRE(idx.cols() == n);
    Eigen::VectorXd c(n);
    for (int k = 0; k < n; ++k) c(k) = U(rng);
    Eigen::VectorXd f(n);
    for (int k = 0; k < n; ++k)
      f(k) = tetrahedron_bezier_value(d, c, idx.col(k).cast<double>() / std::max(d, 1));
    // The collocation matrix's inverse loses digits with the degree: 1e-9 at d = 12.
    const double tol = d <= 9 ? 1e-10 : 1e-8;
    CHECK((tetrahedron_bezier_from_values(d, f) - c).cwiseAbs().maxCoeff() < tol);
    // The corner coefficients are the corner values.
    const int last = d > 0 ? tetrahedron_bezier_size(d - 1) : 0;
    CHECK(c(0) == Approx(tetrahedron_bezier_value(d, c, {0, 0, 0})).margin(1e-14));
    if (d > 0) {
      CHECK(c(last) == Approx(tetrahedron_bezier_value(d, c, {1, 0, 0})).margin(1e-14));
      CHECK(c(last + d) == Approx(tetrahedron_bezier_value(d, c, {0, 1, 0})).margin(1e-14));
      CHECK(c(n - 1) == Approx(tetrahedron_bezier_value(d, c, {0, 0, 1})).margin(1e-14));
    }
    // A constant has every coefficient equal to it.
    CHECK((tetrahedron_bezier_from_values(d, Eigen::VectorXd::Constant(n, 2.5)).array() - 2.5)
              .abs()
              .maxCoeff() < tol);
  }
  CHECK_THROWS_AS(tetrahedron_bezier_indices(kMaxTetBezierDegree + 1), Error);
  CHECK_THROWS_AS(tetrahedron_bezier_from_values(2, Eigen::VectorXd::Zero(3)), Error);
}

TEST_CASE(
    "tetrahedron Bezier subdivision: 8 children of an eighth of the volume, each the "
    "parent polynomial on it",
    "[quality][bezier]") {
  double volume = 0;
  for (int s = 0; s < 8; ++s) {
    const Eigen::Matrix<double, 3, 4> W = tetrahedron_child(s);
    Eigen::Matrix3d E;
    E << W.col(1) - W.col(0), W.col(2) - W.col(0), W.col(3) - W.col(0);
    const double v = std::abs(E.determinant()) / 6;
    CHECK(v == Approx(1.0 / 48));
    volume += v;
  }
  CHECK(volume == Approx(1.0 / 6));
  CHECK_THROWS_AS(tetrahedron_child(8), Error);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int d : {1, 2, 3, 6, 9, 12}) {
    INFO("d = " << d);
    const int n = tetrahedron_bezier_size(d);
    Eigen::VectorXd c(n);
    for (int k = 0; k < n; ++k) c(k) = U(rng);
    Eigen::MatrixXd sub(n, 8);
    tetrahedron_bezier_subdivide(d, c, sub);
    for (int s = 0; s < 8; ++s) {
      const Eigen::Matrix<double, 3, 4> W = tetrahedron_child(s);
      for (int t = 0; t < 5; ++t) {
        const Eigen::Vector3d y = random_point(rng);
        const Eigen::Vector3d x =
            W.col(0) * (1 - y.sum()) + W.col(1) * y(0) + W.col(2) * y(1) + W.col(3) * y(2);
        CHECK(tetrahedron_bezier_value(d, sub.col(s), y) ==
              Approx(tetrahedron_bezier_value(d, c, x)).margin(1e-9));
      }
    }
  }
}
