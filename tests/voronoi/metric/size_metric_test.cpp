#include "voronoi/metric/size_metric.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "voronoi/seeding/curve_division.h"

using namespace homesh;

TEST_CASE("an iso metric from the sizes of a reference mesh", "[voronoi][sizes]") {
  // Two triangles over [0, 2] x [0, 1] with sizes 0.1 at x = 0 and 0.3 at
  // x = 2: linear in x inside, and the mean edge length of a node.
  Eigen::Matrix2Xd x(2, 4);
  x << 0, 2, 2, 0,  //
      0, 0, 1, 1;
  Eigen::MatrixXi tri(3, 2);
  tri << 0, 0,  //
      1, 2,     //
      2, 3;
  const Eigen::VectorXd mean = mean_edge_length(x, tri);
  CHECK(mean(1) == Approx((2.0 + 1.0) / 2));
  CHECK(mean(0) == Approx((2.0 + 2 * std::sqrt(5.0) + 1.0) / 4));  // the diagonal twice
  const Eigen::VectorXd h = (Eigen::VectorXd(4) << 0.1, 0.3, 0.3, 0.1).finished();
  const CartesianGrid coarse = CartesianGrid::spanning({-1, 0}, {2, 1}, 31, 11);
  const MetricField m = iso_metric_from_sizes(coarse, x, h, tri);
  for (int j = 0; j < coarse.ny; ++j)
    for (int i = 0; i < coarse.nx; ++i) {
      const Eigen::Vector2d p = coarse.point(i, j);
      const double want = p.x() >= 0 ? 0.1 + 0.1 * p.x() : 0.1;  // outside: nearest sized node
      const Eigen::Matrix2d M = m.metric(coarse.index(i, j));
      CHECK(M(0, 1) == 0.0);
      CHECK(1 / std::sqrt(M(0, 0)) == Approx(want).epsilon(1e-9));
    }
}

TEST_CASE("a boundary-layer metric is fine across the wall and relaxes", "[voronoi][sizes]") {
  // Wall y = 0 along x; size 0.1: across it 0.02 at the wall, 0.1 beyond 0.3.
  const CartesianGrid coarse = CartesianGrid::spanning({0, 0}, {1, 1}, 21, 21);
  const MetricField iso(coarse, std::vector<Eigen::Matrix2d>(coarse.node_count(),
                                                             Eigen::Matrix2d::Identity() / 0.01));
  Eigen::Matrix2Xd wall(2, 101);
  for (int k = 0; k <= 100; ++k) wall.col(k) << 0.01 * k, 0.0;
  const MetricField bl = boundary_layer_metric(iso, {wall});
  for (int j = 0; j < coarse.ny; ++j) {
    const double y = coarse.point(0, j).y();
    const Eigen::Matrix2d M = bl.metric(coarse.index(10, j));
    const double hn = y < 0.3 ? 0.1 * (0.2 + 0.8 * y / 0.3) : 0.1;
    CHECK(1 / std::sqrt(M(1, 1)) == Approx(hn).epsilon(1e-9));
    CHECK(1 / std::sqrt(M(0, 0)) == Approx(0.1).epsilon(1e-9));
    CHECK(M(0, 1) == Approx(0.0).margin(1e-9));
  }
  // Twice the aspect, twice the thickness: 0.01 across at the wall, 0.1
  // beyond 0.6; an aspect below 1 or no thickness is refused.
  BoundaryLayerOptions o;
  o.wall_aspect = 10;
  o.thickness = 6;
  const MetricField bl10 = boundary_layer_metric(iso, {wall}, o);
  CHECK(1 / std::sqrt(bl10.metric(coarse.index(10, 0))(1, 1)) == Approx(0.01).epsilon(1e-9));
  CHECK(1 / std::sqrt(bl10.metric(coarse.index(10, 6))(1, 1)) ==
        Approx(0.1 * (0.1 + 0.9 * 0.3 / 0.6)).epsilon(1e-9));
  o.wall_aspect = 0.5;
  CHECK_THROWS_WITH(boundary_layer_metric(iso, {wall}, o), Catch::Contains("wall aspect"));
  o.wall_aspect = 5;
  o.thickness = 0;
  CHECK_THROWS_WITH(boundary_layer_metric(iso, {wall}, o), Catch::Contains("thickness"));
}

TEST_CASE("a curve divided into pieces of unit metric length", "[voronoi][sizes]") {
  // The unit circle, size 2 pi / 40: 40 equal pieces; with the size
  // doubled on the left half (x < 0 in the coarse field) fewer pieces there.
  const int n = 4000;
  Eigen::VectorXd u(n + 1);
  Eigen::Matrix2Xd x(2, n + 1);
  for (int k = 0; k <= n; ++k) {
    u(k) = 2 * M_PI * k / n;
    x.col(k) << std::cos(u(k)), std::sin(u(k));
  }
  const double h = 2 * M_PI / 40;
  const auto p = divide_by_metric_length(
      u, x, MetricField::constant(Eigen::Matrix2d::Identity() / (h * h)), 3);
  REQUIRE(p.size() == 41);
  for (std::size_t k = 0; k < p.size(); ++k) CHECK(p[k] == Approx(2 * M_PI * k / 40).margin(1e-9));
  // Too long for one piece at this size: at least min_pieces anyway.
  CHECK(divide_by_metric_length(u, x, MetricField::constant(Eigen::Matrix2d::Identity() / 100), 3)
            .size() == 4);
}
