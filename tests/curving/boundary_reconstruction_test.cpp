// Boundary curves rebuilt from a linear boundary: fourth-order accurate on
// circles, straight between corners, corners chosen by the threshold angle.
#include "curving/boundary_reconstruction.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.h"

using namespace homesh;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Boundary lines of order p through the columns of v (a closed polygon if
// `closed`), each line's interior nodes on its chord; line k takes entity
// entity[k] and runs backwards (from v[k+1] to v[k]) when k is odd, so both
// orientations are exercised. No triangles.
Mesh polygon(const Eigen::Matrix2Xd& v, int p, bool closed, const std::vector<int>& entity) {
  const int n = static_cast<int>(v.cols());
  const int lines = closed ? n : n - 1;
  Mesh m;
  m.order = p;
  m.x.resize(2, n + lines * (p - 1));
  m.x.leftCols(n) = v;
  m.node_class.assign(m.x.cols(), NodeClass{1, 1});
  m.line.resize(p + 1, lines);
  for (int k = 0; k < lines; ++k) {
    const int a = k % 2 ? (k + 1) % n : k, b = k % 2 ? k : (k + 1) % n;
    m.line(0, k) = a;
    m.line(1, k) = b;
    for (int j = 2; j <= p; ++j) {
      const int node = n + k * (p - 1) + j - 2;
      m.line(j, k) = node;
      m.x.col(node) = v.col(a) + (v.col(b) - v.col(a)) * (j - 1.0) / p;
    }
    m.line_entity.push_back(entity[k]);
  }
  return m;
}

Eigen::Matrix2Xd circle_points(int n, double radius) {
  Eigen::Matrix2Xd v(2, n);
  for (int i = 0; i < n; ++i)
    v.col(i) << radius * std::cos(2 * kPi * i / n), radius * std::sin(2 * kPi * i / n);
  return v;
}

// Largest distance of the placed interior line nodes from the circle.
double circle_error(const Mesh& m, const Eigen::Matrix2Xd& x, double radius) {
  double worst = 0;
  for (int k = 0; k < m.num_lines(); ++k)
    for (int j = 2; j <= m.order; ++j)
      worst = std::max(worst, std::abs(x.col(m.line(j, k)).norm() - radius));
  return worst;
}

// Largest distance of the interior line nodes from their line's chord.
double chord_deviation(const Mesh& m, const Eigen::Matrix2Xd& x) {
  double worst = 0;
  for (int k = 0; k < m.num_lines(); ++k) {
    const Eigen::Vector2d a = x.col(m.line(0, k)), b = x.col(m.line(1, k));
    const Eigen::Vector2d d = (b - a).normalized();
    for (int j = 2; j <= m.order; ++j) {
      const Eigen::Vector2d q = x.col(m.line(j, k)) - a;
      worst = std::max(worst, std::abs(d.x() * q.y() - d.y() * q.x()));
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("boundary reconstruction: a circle's polygon is rebuilt to O(h^4)", "[curving]") {
  const double radius = 0.7;
  for (bool split : {false, true}) {
    CAPTURE(split);
    std::vector<double> errors;
    for (int n : {12, 24, 48, 96}) {
      // split: two entities meeting at vertices 0 and n / 2, two open chains.
      std::vector<int> entity(n, 1);
      for (int k = n / 2; k < n && split; ++k) entity[k] = 2;
      const Mesh m = polygon(circle_points(n, radius), 2, true, entity);
      const BoundaryReconstruction b = reconstruct_boundary(m);
      REQUIRE(b.closed_loops == (split ? 0 : 1));
      REQUIRE(b.chains == (split ? 2 : 0));
      REQUIRE(b.corners == 0);
      errors.push_back(circle_error(m, b.target, radius));
      REQUIRE(b.target.leftCols(n) == m.x.leftCols(n));
    }
    for (std::size_t i = 1; i < errors.size(); ++i) {
      const double order = std::log2(errors[i - 1] / errors[i]);
      INFO("N = " << (12 << i) << ": error " << errors[i] << ", observed order " << order);
      CHECK(order >= 3.5);
    }
    CHECK(errors[1] < (split ? 1.5e-4 : 1.5e-5) * radius);
  }
}

TEST_CASE("boundary reconstruction: nodes at equal arc length in either line direction",
          "[curving]") {
  const int n = 48, p = 4;
  const Mesh m = polygon(circle_points(n, 1.0), p, true, std::vector<int>(n, 1));
  const BoundaryReconstruction b = reconstruct_boundary(m);
  double worst = 0;
  for (int k = 0; k < n; ++k) {
    const double a0 = std::atan2(m.x(1, m.line(0, k)), m.x(0, m.line(0, k)));
    double step = std::atan2(m.x(1, m.line(1, k)), m.x(0, m.line(1, k))) - a0;
    step = std::remainder(step, 2 * kPi);
    for (int j = 2; j <= p; ++j) {
      const Eigen::Vector2d q = b.target.col(m.line(j, k));
      const double angle = std::remainder(std::atan2(q.y(), q.x()) - a0, 2 * kPi);
      worst = std::max(worst, std::abs(angle - step * (j - 1.0) / p));
    }
  }
  INFO("worst angle error " << worst);
  REQUIRE(worst < 1e-6);
  REQUIRE(circle_error(m, b.target, 1.0) < 1e-6);
}

TEST_CASE("boundary reconstruction: a square keeps its corners, its sides stay straight",
          "[curving]") {
  // 4 vertices per side, one entity: only the angle makes the corners.
  Eigen::Matrix2Xd v(2, 16);
  const Eigen::Vector2d corner[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int s = 0; s < 4; ++s)
    for (int i = 0; i < 4; ++i)
      v.col(4 * s + i) = corner[s] + (corner[(s + 1) % 4] - corner[s]) * i / 4.0;
  const Mesh m = polygon(3.0 * v, 3, true, std::vector<int>(16, 7));
  const BoundaryReconstruction b = reconstruct_boundary(m);
  REQUIRE(b.corners == 4);
  REQUIRE(b.chains == 4);
  REQUIRE(b.closed_loops == 0);
  REQUIRE(chord_deviation(m, b.target) <= 1e-14);
  // Equal spacing along each straight side.
  REQUIRE((b.target - m.x).cwiseAbs().maxCoeff() <= 1e-14);
}

TEST_CASE("boundary reconstruction: the corner threshold decides which vertices stay sharp",
          "[curving]") {
  // A regular octagon turns 45 degrees at every vertex.
  const Mesh m = polygon(circle_points(8, 1.0), 2, true, std::vector<int>(8, 1));
  BoundaryReconstructionOptions opt;
  opt.corner_degrees = 44;
  BoundaryReconstruction b = reconstruct_boundary(m, opt);
  REQUIRE(b.corners == 8);
  REQUIRE(b.chains == 8);
  REQUIRE(chord_deviation(m, b.target) <= 1e-15);

  opt.corner_degrees = 46;
  b = reconstruct_boundary(m, opt);
  REQUIRE(b.corners == 0);
  REQUIRE(b.closed_loops == 1);
  // Smooth: the mid-nodes bulge outwards, towards the circumscribed circle.
  const double chord_mid = std::cos(kPi / 8);
  for (int k = 0; k < 8; ++k) {
    const double r = b.target.col(m.line(2, k)).norm();
    REQUIRE(r > chord_mid + 0.05);
    REQUIRE(r == Approx(1.0).epsilon(0.01));
  }

  opt.corner_degrees = 180;
  REQUIRE_THROWS_AS(reconstruct_boundary(m, opt), Error);
  opt.corner_degrees = 0;
  REQUIRE_THROWS_AS(reconstruct_boundary(m, opt), Error);
}

TEST_CASE("boundary reconstruction: open chains, branch points and linear lines", "[curving]") {
  // An open polyline: its two ends are chain ends whatever the angle.
  Eigen::Matrix2Xd v(2, 5);
  v << 0, 1, 2, 3, 4, 0, 0.5, 0.8, 0.9, 0.95;
  Mesh m = polygon(v, 2, false, std::vector<int>(4, 1));
  BoundaryReconstruction b = reconstruct_boundary(m);
  REQUIRE(b.chains == 1);
  REQUIRE(b.corners == 0);
  REQUIRE(chord_deviation(m, b.target) > 1e-3);

  // Order 1: nothing to place.
  Mesh linear = polygon(circle_points(6, 1.0), 1, true, std::vector<int>(6, 1));
  b = reconstruct_boundary(linear);
  REQUIRE(b.target == linear.x);

  // Zero-length line.
  Eigen::Matrix2Xd twice(2, 3);
  twice << 0, 1, 1, 0, 0, 0;
  m = polygon(twice, 2, false, {1, 1});
  REQUIRE_THROWS_AS(reconstruct_boundary(m), Error);
}
