#include "curving/interior_blending.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <functional>

#include "element/quad_reference_nodes.h"
#include "element/reference_nodes.h"
#include "quality/jacobian_bounds.h"

using namespace homesh;

namespace {

// The nodes of the order-p triangle that is the image of the reference one under F.
Eigen::Matrix2Xd mapped(int p, const std::function<Eigen::Vector2d(double, double)>& F) {
  const Eigen::Matrix2Xd uv = reference_nodes(p);
  Eigen::Matrix2Xd X(2, uv.cols());
  for (Eigen::Index i = 0; i < uv.cols(); ++i) X.col(i) = F(uv(0, i), uv(1, i));
  return X;
}

// Triangle (1, 0), (cos a, sin a), (0, 0) of order p whose edge 0-1 follows the unit circle
// (its nodes equally spaced in angle), the other edges and the interior straight.
Eigen::Matrix2Xd sector(int p, double a) {
  Eigen::Matrix2Xd X = mapped(p, [&](double u, double v) -> Eigen::Vector2d {
    return (1 - u - v) * Eigen::Vector2d(1, 0) + u * Eigen::Vector2d(std::cos(a), std::sin(a));
  });
  for (int j = 1; j < p; ++j) {
    const double t = a * j / p;
    X.col(3 + j - 1) = Eigen::Vector2d(std::cos(t), std::sin(t));
  }
  return X;
}

double ratio(const Eigen::Matrix2Xd& X, int p) {
  return scaled_jacobian_ratio(jacobian_bounds(X, p));
}

}  // namespace

TEST_CASE("interior blending reproduces every quadratic map, at any order", "[curving]") {
  auto F = [](double u, double v) -> Eigen::Vector2d {
    return {u + 0.3 * u * v - 0.2 * v * v + 0.1, v + 0.15 * u * u + 0.25 * u * v - 0.3};
  };
  for (int p = 2; p <= 8; ++p) {
    CAPTURE(p);
    const Eigen::Matrix2Xd X = mapped(p, F);
    Eigen::Matrix2Xd straight = X;  // interior moved off, to be restored
    for (Eigen::Index i = 3 * p; i < X.cols(); ++i) straight.col(i) += Eigen::Vector2d(0.1, -0.2);
    CHECK((blend_interior(straight, p) - X).cwiseAbs().maxCoeff() < 1e-13);
  }
}

TEST_CASE("interior blending keeps corners and edges, and straight edges give a straight interior",
          "[curving]") {
  for (int p = 3; p <= 6; ++p) {
    CAPTURE(p);
    const Eigen::Matrix2Xd curved = sector(p, 1.0);
    const Eigen::Matrix2Xd blended = blend_interior(curved, p);
    CHECK((blended.leftCols(3 * p) - curved.leftCols(3 * p)).cwiseAbs().maxCoeff() == 0);
    // A cubic with only a bubble mode, u v (1 - u - v): straight edges, so an affine interior.
    auto affine = [](double u, double v) -> Eigen::Vector2d { return {2 * u + v, v - 0.5 * u}; };
    const Eigen::Matrix2Xd bubble = mapped(p, [&](double u, double v) -> Eigen::Vector2d {
      return affine(u, v) + Eigen::Vector2d(3, 1) * u * v * (1 - u - v);
    });
    CHECK((blend_interior(bubble, p) - mapped(p, affine)).cwiseAbs().maxCoeff() < 1e-13);
  }
}

TEST_CASE(
    "a triangle on a circular arc blended from its edge is better shaped than with its "
    "interior straight",
    "[curving]") {
  // Sector of 60 degrees of the unit disc as one element: the straight interior crowds the
  // arc's bulge into the first row of nodes.
  for (int p = 3; p <= 6; ++p) {
    CAPTURE(p);
    const Eigen::Matrix2Xd straight = sector(p, M_PI / 3);
    const double before = ratio(straight, p), after = ratio(blend_interior(straight, p), p);
    CAPTURE(before, after);
    // 0.48, 0.39, 0.32, 0.28 straight; 0.73 blended at every p (the sector's own map, polar,
    // has a varying Jacobian).
    CHECK(after > before + 0.2);
    CHECK(after > 0.72);
  }
}

namespace {

Eigen::Matrix2Xd mapped_quad(int p, const std::function<Eigen::Vector2d(double, double)>& F) {
  const Eigen::Matrix2Xd uv = quad_reference_nodes(p);
  Eigen::Matrix2Xd X(2, uv.cols());
  for (Eigen::Index i = 0; i < uv.cols(); ++i) X.col(i) = F(uv(0, i), uv(1, i));
  return X;
}

// Quadrilateral (1, 0), (cos a, sin a), r (cos a, sin a), (r, 0) of order p whose edge 0-1
// follows the unit circle (nodes equally spaced in angle), the rest bilinear.
Eigen::Matrix2Xd annular_quad(int p, double a, double r) {
  const Eigen::Vector2d c0(1, 0), c1(std::cos(a), std::sin(a)), c2 = r * c1, c3(r, 0);
  Eigen::Matrix2Xd X = mapped_quad(p, [&](double u, double v) -> Eigen::Vector2d {
    return (1 - u) * (1 - v) * c0 + u * (1 - v) * c1 + u * v * c2 + (1 - u) * v * c3;
  });
  for (int j = 1; j < p; ++j)
    X.col(4 + j - 1) = Eigen::Vector2d(std::cos(a * j / p), std::sin(a * j / p));
  return X;
}

}  // namespace

TEST_CASE("quad blending reproduces every map linear in u or in v, at any order",
          "[curving][quad]") {
  // Sums of g(u) (a + b v) and h(v) (c + d u): what the Coons patch with linear blending
  // reproduces (Gordon & Hall 1973); cubic terms from p = 3.
  auto F = [](int p) {
    const double c = p >= 3 ? 1 : 0;
    return [c](double u, double v) -> Eigen::Vector2d {
      return {u + 0.3 * u * v - 0.2 * v * v + 0.1 * c * u * u * u * v + 0.1,
              v + 0.15 * u * u + 0.25 * u * v - 0.2 * c * u * v * v * v - 0.3};
    };
  };
  for (int p = 2; p <= 8; ++p) {
    CAPTURE(p);
    const Eigen::Matrix2Xd X = mapped_quad(p, F(p));
    Eigen::Matrix2Xd moved = X;
    for (Eigen::Index i = 4 * p; i < X.cols(); ++i) moved.col(i) += Eigen::Vector2d(0.1, -0.2);
    CHECK((blend_quad_interior(moved, p) - X).cwiseAbs().maxCoeff() < 1e-13);
    CHECK(
        (blend_quad_interior(moved, p).leftCols(4 * p) - X.leftCols(4 * p)).cwiseAbs().maxCoeff() ==
        0);
  }
  // u^2 v^2 has no edge trace: a bubble, so blending gives the bilinear map.
  const Eigen::Matrix2Xd bubble = mapped_quad(4, [](double u, double v) -> Eigen::Vector2d {
    return {u + u * u * v * v * (1 - u) * (1 - v), v};
  });
  const Eigen::Matrix2Xd square = mapped_quad(4, [](double u, double v) -> Eigen::Vector2d {
    return {u, v};
  });
  CHECK((blend_quad_interior(bubble, 4) - square).cwiseAbs().maxCoeff() < 1e-13);
}

TEST_CASE("a quadrilateral on a circular arc blended from its edge is better shaped than bilinear",
          "[curving][quad]") {
  for (int p = 2; p <= 6; ++p) {
    CAPTURE(p);
    const Eigen::Matrix2Xd straight = annular_quad(p, M_PI / 3, 0.9);
    const double before = scaled_jacobian_ratio(quad_jacobian_bounds(straight, p)),
                 after = scaled_jacobian_ratio(
                     quad_jacobian_bounds(blend_quad_interior(straight, p), p));
    CAPTURE(before, after);
    // Bilinear: 0.03 to -0.03 (invalid) from p = 3, the arc's sagitta 0.134 being above the
    // thickness 0.1. Blended: 0.337 at every p, the map's own ratio (the quad is 0.1 thick at
    // its ends and 0.22 in the middle, where edge 2 stays straight).
    CHECK(after > before + 0.2);
    CHECK(after > 0.33);
  }
}
