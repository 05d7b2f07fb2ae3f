#include "curving/element_distortion.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "core/raise_order.h"

using namespace homesh;

namespace {

// One straight-sided triangle with corners a, b, c (counter-clockwise), raised
// to order p (its high-order nodes on the straight edges).
Mesh triangle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, int p) {
  Mesh m;
  m.x.resize(2, 3);
  m.x << a, b, c;
  m.node_class.assign(3, {});
  m.tri.resize(3, 1);
  m.tri << 0, 1, 2;
  m.tri_entity = {1};
  return raise_order(m, p);
}

}  // namespace

TEST_CASE(
    "element shape quality: 1 for the equilateral element, sqrt(3)/2 for the right "
    "isosceles one, blind to size and rotation",
    "[curving]") {
  for (int p : {1, 2, 3}) {
    CAPTURE(p);
    const ElementDistortion eq =
        element_distortion(triangle({0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}, p));
    CHECK(eq.shape(0) == Approx(1).epsilon(1e-12));
    // W = J inv(J_ri) of (0,0), (1,0), (0,1): |W|_F^2 = 8/3, det W = 2/sqrt(3),
    // so Q11 = 2 det W / |W|_F^2 = sqrt(3)/2 (Eq 3.44).
    const ElementDistortion right = element_distortion(triangle({0, 0}, {1, 0}, {0, 1}, p));
    CHECK(right.shape(0) == Approx(std::sqrt(3.0) / 2).epsilon(1e-12));
    CHECK(right.q17_ratio(0) == Approx(1).epsilon(1e-12));
    const double c = std::cos(0.7), s = std::sin(0.7);
    const ElementDistortion turned =
        element_distortion(triangle({3, 1}, {3 + 5 * c, 1 + 5 * s}, {3 - 5 * s, 1 + 5 * c}, p));
    CHECK(turned.shape(0) == Approx(std::sqrt(3.0) / 2).epsilon(1e-12));
    CHECK(turned.area(0) == Approx(12.5).epsilon(1e-12));
  }
}

TEST_CASE("element shape quality sees shear that the Q17 ratio cannot, and drops with a bent edge",
          "[curving]") {
  // A straight-sided sheared triangle: det J is constant, so min Q17/max Q17 = 1,
  // while its shape is far from equilateral.
  const ElementDistortion sheared = element_distortion(triangle({0, 0}, {1, 0}, {3, 0.4}, 2));
  CHECK(sheared.q17_ratio(0) == Approx(1).epsilon(1e-12));
  CHECK(sheared.shape(0) < 0.3);
  // Bending an edge of the equilateral quadratic element lowers both.
  Mesh bent = triangle({0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}, 2);
  bent.x(1, bent.tri(3, 0)) += 0.15;  // mid-node of edge 0-1 pushed inward
  const ElementDistortion b = element_distortion(bent);
  CHECK(b.shape(0) < 0.95);
  CHECK(b.q17_ratio(0) < 0.95);
  CHECK(b.shape(0) > 0);
  // Pushed through the opposite corner, the element is invalid: shape 0.
  bent.x(1, bent.tri(3, 0)) += 1.0;
  CHECK(element_distortion(bent).shape(0) == 0);
}
