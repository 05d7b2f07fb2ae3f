#include "quality/bezier_triangle.h"

#include <catch2/catch.hpp>
#include <random>

#include "core/error.h"
#include "element/reference_nodes.h"
#include "reference_points.h"

using namespace homesh;

TEST_CASE("Bernstein basis: non-negative partition of unity, unit at the corners", "[bezier]") {
  std::mt19937 rng(1);
  for (int d = 0; d <= 12; ++d) {
    INFO("d = " << d);
    REQUIRE(bernstein_basis(d, Eigen::Vector2d(0.2, 0.3)).size() == bezier_size(d));
    for (int q = 0; q < 50; ++q) {
      const Eigen::VectorXd B = bernstein_basis(d, test::random_reference_point(rng));
      CHECK(B.minCoeff() >= 0.0);
      CHECK(B.sum() == Approx(1.0).epsilon(1e-14));
    }
    const Eigen::Vector2d corners[3] = {{0, 0}, {1, 0}, {0, 1}};
    const int corner_index[3] = {0, d, bezier_size(d) - 1};
    for (int c = 0; c < 3; ++c) {
      const Eigen::VectorXd B = bernstein_basis(d, corners[c]);
      CHECK(B(corner_index[c]) == 1.0);
      CHECK(B.sum() == 1.0);
    }
  }
}

TEST_CASE("Bernstein basis: the coordinates have the domain points as coefficients", "[bezier]") {
  // u = sum_ijk (j/d) B_ijk and v = sum_ijk (k/d) B_ijk (linear precision).
  std::mt19937 rng(2);
  for (int d = 1; d <= 10; ++d) {
    Eigen::VectorXd cu(bezier_size(d)), cv(bezier_size(d));
    for (int k = 0; k <= d; ++k) {
      for (int j = 0; j + k <= d; ++j) {
        cu(bezier_index(d, j, k)) = double(j) / d;
        cv(bezier_index(d, j, k)) = double(k) / d;
      }
    }
    for (int q = 0; q < 20; ++q) {
      const Eigen::Vector2d uv = test::random_reference_point(rng);
      CHECK(bezier_value(d, cu, uv) == Approx(uv(0)).margin(1e-14));
      CHECK(bezier_value(d, cv, uv) == Approx(uv(1)).margin(1e-14));
    }
  }
}

TEST_CASE("Bernstein basis: a known product, (u v) in degree 2", "[bezier]") {
  // u v = l1 l2 = B_011 / 2: the only non-zero coefficient is 1/2 at (j, k) = (1, 1).
  Eigen::VectorXd c = Eigen::VectorXd::Zero(bezier_size(2));
  c(bezier_index(2, 1, 1)) = 0.5;
  const Eigen::Vector2d uv(0.3, 0.45);
  CHECK(bezier_value(2, c, uv) == Approx(0.3 * 0.45).epsilon(1e-15));
  CHECK(bezier_index(2, 1, 1) == 4);
}

TEST_CASE("lagrange_to_bezier recovers the coefficients from values at the Gmsh nodes",
          "[bezier]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
  for (int d = 1; d <= 10; ++d) {
    INFO("d = " << d);
    const Eigen::Matrix2Xd nodes = reference_nodes(d);
    const Eigen::MatrixXd T = lagrange_to_bezier(d, nodes);
    Eigen::VectorXd c(bezier_size(d));
    for (int i = 0; i < c.size(); ++i) c(i) = coefficient(rng);
    Eigen::VectorXd f(nodes.cols());
    for (int m = 0; m < nodes.cols(); ++m) f(m) = bezier_value(d, c, nodes.col(m));
    CHECK((T * f - c).cwiseAbs().maxCoeff() < 1e-10);
    // The corner nodes (Gmsh nodes 0, 1, 2) give the corner coefficients exactly.
    for (int corner = 0; corner < 3; ++corner) {
      const int index = corner == 0 ? 0 : corner == 1 ? d : bezier_size(d) - 1;
      CHECK(std::abs(T(index, corner) - 1.0) < 1e-10);
    }
  }
}

TEST_CASE("lagrange_to_bezier rejects bad node sets", "[bezier]") {
  CHECK_THROWS_AS(lagrange_to_bezier(2, reference_nodes(3)), Error);
  Eigen::Matrix2Xd collinear(2, 3);
  collinear << 0, 0.5, 1, 0, 0, 0;
  CHECK_THROWS_AS(lagrange_to_bezier(1, collinear), Error);
}
