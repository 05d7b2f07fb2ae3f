#include "quality/jacobian_bounds.h"

#include <catch2/catch.hpp>
#include <limits>
#include <random>
#include <vector>

#include "core/error.h"
#include "element/jacobian.h"
#include "element/lagrange_basis.h"
#include "element/reference_nodes.h"
#include "quality/bezier_jacobian.h"
#include "quality/bezier_triangle.h"
#include "reference_points.h"

using namespace homesh;

namespace {

// An order-p triangle: the nodes of a random counter-clockwise straight triangle
// of unit size, the non-corner ones displaced by up to `amplitude` / p.
Eigen::Matrix2Xd curved_triangle(int p, double amplitude, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.3, 0.3), unit(-1.0, 1.0);
  Eigen::Matrix2d A;
  A << 1.0 + jitter(rng), 0.5 + jitter(rng), jitter(rng), 0.9 + jitter(rng);
  Eigen::Matrix2Xd X = A * reference_nodes(p);
  for (int i = 3; i < X.cols(); ++i)
    X.col(i) += amplitude / p * Eigen::Vector2d(unit(rng), unit(rng));
  return X;
}

double direct_det_j(const LagrangeBasis& basis, const Eigen::Matrix2Xd& X,
                    const Eigen::Vector2d& uv) {
  return jacobian(X, basis.gradients(uv)).determinant();
}

// Quadratic triangle (0,0), (1,0), (0,1), straight edges, the mid-node of edge
// 0-1 at (t, 0) and that of edge 2-0 at (0, s); edge 1-2's at (1/2, 1/2).
Eigen::Matrix2Xd slid_quadratic(double t, double s) {
  Eigen::Matrix2Xd X(2, 6);
  X << 0, 1, 0, t, 0.5, 0,  //
      0, 0, 1, 0, 0.5, s;
  return X;
}

}  // namespace

TEST_CASE("straight-sided triangles: det J = 2 * area, exact bounds, ratio 1", "[bounds]") {
  std::mt19937 rng(11);
  for (int p = 1; p <= 6; ++p) {
    INFO("p = " << p);
    const Eigen::Matrix2Xd X = curved_triangle(p, 0.0, rng);
    const Eigen::Vector2d e1 = X.col(1) - X.col(0), e2 = X.col(2) - X.col(0);
    const double two_area = e1(0) * e2(1) - e1(1) * e2(0);
    REQUIRE(two_area > 0);
    const JacobianBounds b = jacobian_bounds(X, p);
    for (const double value : {b.min_lower, b.min_upper, b.max_lower, b.max_upper}) {
      CHECK(value == Approx(two_area).epsilon(1e-13));
    }
    CHECK(b.subdivisions == 0);
    CHECK(b.converged);
    CHECK(b.valid_certified);
    CHECK_FALSE(b.invalid_certified);
    CHECK(scaled_jacobian_ratio(b) == Approx(1.0).epsilon(1e-13));

    // Its mirror image (x, y) -> (y, x) is clockwise: det J = -2 * area,
    // reported negative as Gmsh does, an inverted element, ratio still 1.
    Eigen::Matrix2Xd Y(2, X.cols());
    Y.row(0) = X.row(1);
    Y.row(1) = X.row(0);
    const JacobianBounds c = jacobian_bounds(Y, p);
    CHECK(c.min_lower == Approx(-two_area).epsilon(1e-13));
    CHECK(c.max_upper == Approx(-two_area).epsilon(1e-13));
    CHECK(c.invalid_certified);
    CHECK_FALSE(c.valid_certified);
    CHECK(scaled_jacobian_ratio(c) == Approx(1.0).epsilon(1e-13));
  }
}

TEST_CASE("Bezier coefficients of det J reproduce det J", "[bounds]") {
  std::mt19937 rng(12);
  for (int p = 1; p <= 6; ++p) {
    INFO("p = " << p);
    const LagrangeBasis basis(p);
    const int d = 2 * (p - 1);
    for (const double amplitude : {0.2, 1.0}) {
      const Eigen::Matrix2Xd X = curved_triangle(p, amplitude, rng);
      const Eigen::VectorXd c = jacobian_determinant_bezier(X, p);
      REQUIRE(c.size() == bezier_size(d));
      for (int q = 0; q < 200; ++q) {
        const Eigen::Vector2d uv = test::random_reference_point(rng);
        CHECK(bezier_value(d, c, uv) == Approx(direct_det_j(basis, X, uv)).margin(1e-12));
      }
    }
  }
  CHECK_THROWS_AS(jacobian_determinant_bezier(Eigen::Matrix2Xd::Zero(2, 6), 3), Error);
  CHECK_THROWS_AS(jacobian_determinant_bezier(Eigen::Matrix2Xd::Zero(2, 6), 0), Error);
}

TEST_CASE("derivative control points reproduce J, every order to 10", "[bounds]") {
  std::mt19937 rng(17);
  for (int p = 1; p <= 10; ++p) {
    INFO("p = " << p);
    const LagrangeBasis basis(p);
    const Eigen::Matrix2Xd X = curved_triangle(p, 0.5, rng);
    JacobianControlPoints U(2, bezier_size(p - 1)), V(2, bezier_size(p - 1));
    jacobian_control_points(X, p, U, V);
    // The coefficients of det J from them are those from the nodes.
    Eigen::VectorXd c(bezier_size(2 * (p - 1)));
    jacobian_determinant_bezier(U, V, p, c);
    CHECK((c - jacobian_determinant_bezier(X, p)).cwiseAbs().maxCoeff() == 0.0);
    for (int q = 0; q < 50; ++q) {
      const Eigen::Vector2d uv = test::random_reference_point(rng);
      const Eigen::VectorXd B = bernstein_basis(p - 1, uv);
      Eigen::Matrix2d J;
      J << p * U * B, p * V * B;
      const Eigen::Matrix2d direct = jacobian(X, basis.gradients(uv));
      CHECK((J - direct).cwiseAbs().maxCoeff() < 1e-12 * direct.cwiseAbs().maxCoeff());
    }
  }
  JacobianControlPoints U(2, 3), V(2, 3);
  CHECK_THROWS_AS(jacobian_control_points(Eigen::Matrix2Xd::Zero(2, 6), 3, U, V), Error);
}

TEST_CASE("bounds contain det J at 10^4 random points, valid and invalid elements", "[bounds]") {
  std::mt19937 rng(13);
  int valid = 0, invalid = 0;
  for (int p = 2; p <= 6; ++p) {
    const LagrangeBasis basis(p);
    for (const double amplitude : {0.1, 0.3, 0.6, 1.2}) {
      INFO("p = " << p << ", amplitude " << amplitude);
      const Eigen::Matrix2Xd X = curved_triangle(p, amplitude, rng);
      const JacobianBounds b = jacobian_bounds(X, p);
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (int q = 0; q < 10000; ++q) {
        const double J = direct_det_j(basis, X, test::random_reference_point(rng));
        lo = std::min(lo, J);
        hi = std::max(hi, J);
      }
      CHECK(b.converged);
      CHECK(b.min_lower <= lo);
      CHECK(hi <= b.max_upper);
      // The exact values found lie within the sampled range up to the tolerance
      // (random points come within ~1e-4 of the extrema, worth < 1e-3 of max|J|).
      CHECK(b.min_upper <= lo + b.tolerance);
      CHECK(b.max_lower >= hi - b.tolerance);
      CHECK(b.min_upper - b.min_lower <= b.tolerance);
      CHECK(b.max_upper - b.max_lower <= b.tolerance);
      CHECK(b.tolerance == Approx(1e-3 * std::max(std::abs(b.min_upper), std::abs(b.max_lower))));
      CHECK(b.valid_certified != b.invalid_certified);
      if (lo <= 0) CHECK(b.invalid_certified);
      valid += b.valid_certified;
      invalid += b.invalid_certified;
    }
  }
  INFO(valid << " valid, " << invalid << " invalid");
  CHECK(valid >= 5);
  CHECK(invalid >= 5);
}

TEST_CASE("quadratic with one mid-node slid along its edge: invalid from t = 1/4", "[bounds]") {
  // Mid-node of edge 0-1 at (t, 0): x = u + 4 (t - 1/2) u (1 - u - v), y = v, so
  // det J = 1 + 4 (t - 1/2)(1 - 2u - v), lowest at corner 0 where it is 4t - 1
  // (thesis element T7), highest at corner 1 where it is 3 - 4t.
  for (const double t : {0.5, 0.3, 0.25 + 1e-6, 0.25, 0.25 - 1e-6, 0.1}) {
    INFO("t = " << t);
    const JacobianBounds b = jacobian_bounds(slid_quadratic(t, 0.5), 2);
    CHECK(b.min_lower == Approx(4 * t - 1).margin(1e-14));
    CHECK(b.min_upper == Approx(4 * t - 1).margin(1e-14));
    CHECK(b.max_upper == Approx(3 - 4 * t).margin(1e-14));
    CHECK(b.converged);
    CHECK(b.valid_certified == (t > 0.25));
    CHECK(b.invalid_certified == (t <= 0.25));
  }
}

TEST_CASE("folded corner: det J > 0 at every node yet invalid, caught by the bounds", "[bounds]") {
  // Both mid-nodes at corner 0 slid to 1/10 of their edges: each edge's
  // parametrisation runs backwards past corner 0 (x = u (1.6 u - 0.6) on edge
  // 0-1), the two edges overlap there and the element folds. At corner 0 the
  // two sign flips cancel: det J = (4t - 1)^2 = 0.36. With d = t - 1/2, on edge
  // 0-1 det J = (1 + 4d (1 - 2u)) (1 + 4d (1 - u)) = (3.2u - 0.6)(1.6u - 0.6),
  // which is -0.045 at u = 0.28125 between the nodes u = 0 and u = 1/2.
  const Eigen::Matrix2Xd X = slid_quadratic(0.1, 0.1);
  const LagrangeBasis basis(2);
  // Gmsh samples det J at the nodes of order 2(p - 1) = 2: the element's own.
  for (int i = 0; i < 6; ++i) CHECK(direct_det_j(basis, X, basis.nodes().col(i)) > 0.19);
  CHECK(direct_det_j(basis, X, Eigen::Vector2d(0.28125, 0)) == Approx(-0.045).margin(1e-15));

  const JacobianBounds b = jacobian_bounds(X, 2);
  CHECK(b.invalid_certified);
  CHECK_FALSE(b.valid_certified);
  CHECK(b.converged);
  CHECK(b.subdivisions > 0);
  CHECK(b.min_lower <= -0.045);
  CHECK(b.min_upper < -0.045 + b.tolerance);
  // Gmsh 4.8's AnalyseMeshQuality reports minJ/maxJ = -0.0173077 = -0.045 / 2.6.
  CHECK(scaled_jacobian_ratio(b) == Approx(-0.045 / 2.6).epsilon(1e-9));
}

TEST_CASE("tolerance and subdivision budget", "[bounds]") {
  std::mt19937 rng(14);
  const Eigen::Matrix2Xd X = curved_triangle(4, 0.4, rng);
  int previous = -1;
  for (const double tolerance : {1e-1, 1e-3, 1e-6}) {
    INFO("relative tolerance " << tolerance);
    BoundsOptions opt;
    opt.relative_tolerance = tolerance;
    const JacobianBounds b = jacobian_bounds(X, 4, opt);
    CHECK(b.converged);
    CHECK(b.min_upper - b.min_lower <= b.tolerance);
    CHECK(b.max_upper - b.max_lower <= b.tolerance);
    CHECK(b.tolerance <= tolerance * b.max_upper);
    CHECK(b.subdivisions > previous);
    previous = b.subdivisions;
  }
  // Without subdivisions the bounds are the extreme coefficients: still valid, not converged.
  BoundsOptions none;
  none.max_subdivisions = 0;
  none.relative_tolerance = 1e-6;
  const JacobianBounds coarse = jacobian_bounds(X, 4, none);
  const Eigen::VectorXd c = jacobian_determinant_bezier(X, 4);
  CHECK(coarse.subdivisions == 0);
  CHECK_FALSE(coarse.converged);
  CHECK(coarse.min_lower == c.minCoeff());
  CHECK(coarse.max_upper == c.maxCoeff());

  BoundsOptions bad;
  bad.relative_tolerance = -1;
  CHECK_THROWS_AS(jacobian_bounds(X, 4, bad), Error);
  CHECK_THROWS_AS(bezier_bounds(2, Eigen::VectorXd::Zero(5)), Error);
  Eigen::Matrix2Xd broken = X;
  broken(0, 7) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(jacobian_bounds(broken, 4), Error);
}

TEST_CASE("scaled ratio follows Gmsh's minJ/maxJ", "[bounds]") {
  JacobianBounds b;
  b.min_lower = 0.5;
  b.max_upper = 2.0;
  CHECK(scaled_jacobian_ratio(b) == 0.25);
  b.min_lower = -1.0;
  CHECK(scaled_jacobian_ratio(b) == -0.5);
  b.min_lower = -4.0;
  b.max_upper = -1.0;
  CHECK(scaled_jacobian_ratio(b) == 0.25);
  b.max_upper = 0.0;
  CHECK(scaled_jacobian_ratio(b) == 0.0);
}

TEST_CASE("scaled ratio matches Gmsh's AnalyseMeshQuality on curved elements", "[bounds]") {
  // "minJ/maxJ 2D" of Gmsh 4.8's AnalyseMeshQuality plugin (JacobianDeterminant = 1)
  // for single elements added as a discrete surface. Each needs subdivisions.
  struct Case {
    int p;
    double gmsh_ratio;
    std::vector<double> x, y;
  };
  const std::vector<Case> cases = {
      {3,
       0.9044041509150115,
       {0.0, 1.206, 0.379, 0.407, 0.804, 0.925, 0.659, 0.258, 0.13, 0.522},
       {0.0, 0.08, 0.844, 0.026, 0.052, 0.33, 0.592, 0.564, 0.283, 0.306}},
      {4,
       0.8272615442121853,
       {0.0, 0.929, 0.256, 0.232, 0.466, 0.692, 0.762, 0.595, 0.422, 0.192, 0.133, 0.067, 0.293,
        0.523, 0.364},
       {0.0, 0.056, 1.175, 0.017, 0.025, 0.042, 0.334, 0.612, 0.9, 0.881, 0.587, 0.298, 0.31, 0.319,
        0.598}},
      {4,
       -0.13966738780619906,
       {0.0, 1.214, 0.406, 0.365, 0.617, 0.857, 0.992, 0.77, 0.543, 0.346, 0.149, 0.086, 0.342,
        0.734, 0.489},
       {0.0, -0.078, 1.106, 0.054, 0.013, -0.038, 0.249, 0.492, 0.814, 0.831, 0.511, 0.268, 0.289,
        0.279, 0.526}},
      {5,
       0.711447627083437,
       {0.0,   0.787, 0.534, 0.156, 0.317, 0.471, 0.627, 0.735, 0.688, 0.635, 0.585,
        0.423, 0.319, 0.213, 0.107, 0.261, 0.582, 0.474, 0.422, 0.532, 0.372},
       {0.0,   0.261, 0.887, 0.049, 0.107, 0.16,  0.21,  0.39, 0.511, 0.635, 0.764,
        0.707, 0.536, 0.353, 0.179, 0.226, 0.331, 0.585, 0.28, 0.459, 0.407}},
  };
  for (const Case& c : cases) {
    INFO("p = " << c.p);
    Eigen::Matrix2Xd X(2, c.x.size());
    X.row(0) = Eigen::Map<const Eigen::RowVectorXd>(c.x.data(), c.x.size());
    X.row(1) = Eigen::Map<const Eigen::RowVectorXd>(c.y.data(), c.y.size());
    const JacobianBounds b = jacobian_bounds(X, c.p);
    CHECK(b.subdivisions > 0);
    CHECK(scaled_jacobian_ratio(b) == Approx(c.gmsh_ratio).epsilon(1e-10));
  }
}
