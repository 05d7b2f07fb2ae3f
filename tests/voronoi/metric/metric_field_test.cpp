#include "voronoi/metric/metric_field.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.h"

using namespace homesh;

TEST_CASE("metric_from_axes: unit ball with semi-axis h1 at angle theta (Eq 2.7)",
          "[voronoi][metric]") {
  const double theta = 0.5, h1 = 0.6, h2 = 0.2;
  const Eigen::Matrix2d M = metric_from_axes(theta, h1, h2);
  const Eigen::Vector2d major(std::cos(theta), std::sin(theta)),
      minor(-std::sin(theta), std::cos(theta));
  // The points h1 * major and h2 * minor lie on the unit ball's boundary.
  CHECK((h1 * major).dot(M * (h1 * major)) == Approx(1.0).epsilon(1e-14));
  CHECK((h2 * minor).dot(M * (h2 * minor)) == Approx(1.0).epsilon(1e-14));
  CHECK(major.dot(M * minor) == Approx(0.0).margin(1e-14));
  const Eigen::Vector2d lambda = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(M).eigenvalues();
  CHECK(lambda(0) == Approx(1 / (h1 * h1)));
  CHECK(lambda(1) == Approx(1 / (h2 * h2)));
  CHECK(metric_max_speed(M) == Approx(h1));
  CHECK(metric_min_speed(M) == Approx(h2));
  CHECK_THROWS_AS(metric_from_axes(0.0, 0.0, 1.0), Error);
}

TEST_CASE("metric_speed is the support function of the metric's unit ball", "[voronoi][metric]") {
  // h(N) = max over the ellipse x^T M x = 1 of N . x, sampled finely.
  const Eigen::Matrix2d M = metric_from_axes(-1.1, 2.0, 0.25);
  const Eigen::Matrix2d Minv = M.inverse();
  const Eigen::Matrix2d L = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(M).operatorInverseSqrt();
  double worst = 0.0;
  for (int k = 0; k < 32; ++k) {
    const Eigen::Vector2d N(std::cos(0.2 * k), std::sin(0.2 * k));
    double h = -1e300;
    for (int m = 0; m < 20000; ++m) {
      const double a = 2 * M_PI * m / 20000;
      h = std::max(h, N.dot(L * Eigen::Vector2d(std::cos(a), std::sin(a))));
    }
    worst = std::max(worst, std::abs(metric_speed(Minv, N) - h));
  }
  CHECK(worst < 1e-6);
}

TEST_CASE("MetricField: Shepard weights of the 4 corners and the speed average",
          "[voronoi][metric]") {
  const CartesianGrid coarse = CartesianGrid::spanning({0, 0}, {2, 1}, 3, 2);
  std::vector<Eigen::Matrix2d> M;
  for (int k = 0; k < coarse.node_count(); ++k)
    M.push_back(metric_from_axes(0.3 * k, 1.0 + k, 0.5));
  const MetricField field(coarse, M);
  CHECK(field.max_speed() == Approx(6.0));
  CHECK(field.min_speed() == Approx(0.5));

  const Eigen::Vector2d p(1.3, 0.4);
  const ShepardStencil s = field.stencil(p);
  double sum = 0.0, expected_F = 0.0, norm = 0.0;
  const Eigen::Vector2d N(0.6, 0.8);
  for (int k = 0; k < 4; ++k) {
    sum += s.w[k];
    const int i = s.node[k] % coarse.nx, j = s.node[k] / coarse.nx;
    CHECK((i == 1 || i == 2));
    const double w = 1.0 / (coarse.point(i, j) - p).squaredNorm();
    norm += w;
    expected_F += w * metric_speed(M[s.node[k]].inverse(), N);
  }
  CHECK(sum == Approx(1.0));
  CHECK(field.speed(p, N) == Approx(expected_F / norm));
  // At a corner the corner's own value; outside the grid, clamped.
  CHECK(field.speed(coarse.point(2, 1), N) == Approx(metric_speed(M[5].inverse(), N)));
  CHECK(field.speed({5.0, 3.0}, N) == Approx(metric_speed(M[5].inverse(), N)));
  CHECK(field.metric_at(coarse.point(0, 0)).isApprox(M[0]));
  // metric_at, with its single division, is the Shepard average of stencil().
  for (const Eigen::Vector2d& q :
       {p, Eigen::Vector2d(0.2, 0.9), Eigen::Vector2d(2.7, 0.05), Eigen::Vector2d(-1.0, 0.5)}) {
    const ShepardStencil w = field.stencil(q);
    Eigen::Matrix2d average = Eigen::Matrix2d::Zero();
    for (int k = 0; k < 4; ++k) average += w.w[k] * M[w.node[k]];
    CHECK((field.metric_at(q) - average).norm() <= 1e-14 * average.norm());
  }

  CHECK_THROWS_AS(MetricField(coarse, {M[0]}), Error);
  Eigen::Matrix2d bad;
  bad << 1, 0, 0, -1;
  CHECK_THROWS_AS(MetricField::constant(bad), Error);
}

TEST_CASE(
    "MetricField: copies share the nodes' tensors; the inverses, made on first use, are "
    "theirs",
    "[voronoi][metric]") {
  const CartesianGrid coarse = CartesianGrid::spanning({0, 0}, {2, 1}, 3, 2);
  std::vector<Eigen::Matrix2d> M;
  for (int k = 0; k < coarse.node_count(); ++k)
    M.push_back(metric_from_axes(0.4 * k, 2.0 + k, 0.25));
  const MetricField field(coarse, M);
  const MetricField copy = field;  // NOLINT(performance-unnecessary-copy-initialization)
  CHECK(copy == field);
  for (int k = 0; k < coarse.node_count(); ++k) {
    CHECK(field.metric(k) == M[k]);
    CHECK(copy.inverse(k) == M[k].inverse());
  }
  CHECK(&copy.inverse(2) == &field.inverse(2));
  // A field with other tensors is another field, though its grid is the same.
  M[4] *= 2.0;
  CHECK_FALSE(MetricField(coarse, M) == field);
}

TEST_CASE(
    "MetricField: an isotropic field kept as numbers gives, to the bit, the values of its "
    "tensors",
    "[voronoi][metric]") {
  const CartesianGrid coarse = CartesianGrid::spanning({-1, 0}, {2, 1.5}, 5, 4);
  std::vector<double> a;
  std::vector<Eigen::Matrix2d> M;
  for (int k = 0; k < coarse.node_count(); ++k) {
    const double h = 0.05 + 0.013 * k + 0.002 * (k % 3);
    a.push_back(1.0 / (h * h));
    M.push_back(Eigen::Matrix2d::Identity() / (h * h));
  }
  const MetricField numbers = MetricField::isotropic(coarse, a), tensors(coarse, M);
  CHECK(numbers == tensors);
  CHECK(numbers.max_speed() == tensors.max_speed());
  CHECK(numbers.min_speed() == tensors.min_speed());
  CHECK(numbers.anisotropy() == 1.0);
  CHECK_FALSE(numbers.uniform());
  int points = 0;
  for (double x = -1.3; x <= 2.3; x += 0.0731)
    for (double y = -0.2; y <= 1.7; y += 0.0517) {
      const Eigen::Vector2d p(x, y), N(std::cos(x + y), std::sin(x + y));
      CHECK(numbers.metric_at(p) == tensors.metric_at(p));
      CHECK(numbers.speed(p, N) == tensors.speed(p, N));
      ++points;
    }
  CHECK(points > 1000);
  // At a node itself, and its inverse.
  CHECK(numbers.metric_at(coarse.point(2, 1)) == M[coarse.index(2, 1)]);
  CHECK(numbers.inverse(7) == M[7].inverse());
  a[3] = 0.0;
  CHECK_THROWS_AS(MetricField::isotropic(coarse, a), Error);
  a[3] = std::nan("");
  CHECK_THROWS_AS(MetricField::isotropic(coarse, a), Error);
  CHECK_THROWS_AS(MetricField::isotropic(coarse, {1.0, 2.0}), Error);
}
