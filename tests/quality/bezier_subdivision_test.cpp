#include "quality/bezier_subdivision.h"

#include <catch2/catch.hpp>
#include <random>

#include "quality/bezier_triangle.h"
#include "reference_points.h"

using namespace homesh;

namespace {

// The affine maps from the reference triangle onto S0..S3 (bezier_subdivision.h).
Eigen::Vector2d to_parent(int s, const Eigen::Vector2d& uv) {
  switch (s) {
    case 0:
      return uv / 2;
    case 1:
      return Eigen::Vector2d((1 + uv(0)) / 2, uv(1) / 2);
    case 2:
      return Eigen::Vector2d(uv(0) / 2, (1 + uv(1)) / 2);
    default:
      return Eigen::Vector2d((1 - uv(0)) / 2, (1 - uv(1)) / 2);
  }
}

Eigen::VectorXd random_coefficients(int d, std::mt19937& rng) {
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
  Eigen::VectorXd c(bezier_size(d));
  for (int i = 0; i < c.size(); ++i) c(i) = coefficient(rng);
  return c;
}

}  // namespace

TEST_CASE("subdivision: each piece is the polynomial on its sub-triangle", "[bezier]") {
  std::mt19937 rng(7);
  for (int d = 0; d <= 12; ++d) {
    INFO("d = " << d);
    const Eigen::VectorXd c = random_coefficients(d, rng);
    Eigen::MatrixXd sub(bezier_size(d), 4);
    bezier_subdivide(d, c, sub);
    for (int s = 0; s < 4; ++s) {
      INFO("S" << s);
      for (int q = 0; q < 20; ++q) {
        const Eigen::Vector2d uv = test::random_reference_point(rng);
        CHECK(bezier_value(d, sub.col(s), uv) ==
              Approx(bezier_value(d, c, to_parent(s, uv))).margin(1e-12));
      }
      // The corner coefficients are the values at the sub-triangle's corners.
      const Eigen::Vector2d corners[3] = {{0, 0}, {1, 0}, {0, 1}};
      const int corner_index[3] = {0, d, bezier_size(d) - 1};
      for (int k = 0; k < 3; ++k) {
        CHECK(sub(corner_index[k], s) ==
              Approx(bezier_value(d, c, to_parent(s, corners[k]))).margin(1e-12));
      }
      // Nested bounds: the pieces' coefficients lie within the parent's range.
      CHECK(sub.col(s).minCoeff() >= c.minCoeff() - 1e-13);
      CHECK(sub.col(s).maxCoeff() <= c.maxCoeff() + 1e-13);
    }
  }
}

TEST_CASE("subdivision: the control net converges quadratically to the polynomial", "[bezier]") {
  // After L levels (triangles of size h = 2^-L) every coefficient is within
  // O(h^2) of the polynomial's value at its domain point: the error drops
  // towards 4x per level (3.3x to 3.6x here at levels 2 to 5; Dahmen 1986).
  std::mt19937 rng(8);
  const int d = 6;
  const Eigen::VectorXd c = random_coefficients(d, rng);
  std::vector<Eigen::VectorXd> level{c};
  double previous = 0;
  for (int L = 1; L <= 5; ++L) {
    std::vector<Eigen::VectorXd> next;
    double error = 0;
    for (const Eigen::VectorXd& parent : level) {
      Eigen::MatrixXd sub(bezier_size(d), 4);
      bezier_subdivide(d, parent, sub);
      for (int s = 0; s < 4; ++s) {
        next.push_back(sub.col(s));
        for (int k = 0; k <= d; ++k) {
          for (int j = 0; j + k <= d; ++j) {
            const Eigen::Vector2d domain_point(double(j) / d, double(k) / d);
            error = std::max(error, std::abs(sub(bezier_index(d, j, k), s) -
                                             bezier_value(d, sub.col(s), domain_point)));
          }
        }
      }
    }
    INFO("level " << L << " error " << error);
    if (L > 1) CHECK(error < previous / 3.0);  // linear convergence would give 2x
    previous = error;
    level = std::move(next);
  }
}
