#include "voronoi/metric/wall_layer.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "voronoi/metric/size_metric.h"

using namespace homesh;

TEST_CASE("wall distance: to the nearest segment exactly, radial round a polyline's end",
          "[voronoi][sizes]") {
  // An L: (0, 0) -> (1, 0) -> (1, 1), sampled every 0.25.
  Eigen::Matrix2Xd wall(2, 9);
  wall << 0, 0.25, 0.5, 0.75, 1, 1, 1, 1, 1,  //
      0, 0, 0, 0, 0, 0.25, 0.5, 0.75, 1;
  const WallDistance d({wall});
  // Between samples: the perpendicular distance, the tangent along the wall.
  WallDistance::Nearest n = d.nearest_within({0.3, 1e-4}, 1.0);
  CHECK(n.distance == Approx(1e-4).epsilon(1e-9));
  CHECK(std::abs(n.tangent.x()) == Approx(1.0));
  n = d.nearest_within({0.9, 0.6}, 1.0);
  CHECK(n.distance == Approx(0.1));
  CHECK(std::abs(n.tangent.y()) == Approx(1.0));
  // Beyond the end (0, 0): radial, the tangent across (p - end).
  n = d.nearest_within({-0.3, 0.4}, 1.0);
  CHECK(n.distance == Approx(0.5));
  CHECK(std::abs(n.tangent.dot(Eigen::Vector2d(-0.6, 0.8))) < 1e-12);
  // Nothing within the bound: the segment found, if any, lies beyond it; with
  // a bound past it, the nearest, (0, 0) at sqrt(18) from (-3, 3).
  CHECK_FALSE(d.nearest_within({-3, 3}, 1.0).distance < 1.0);
  CHECK(d.nearest_within({-3, 3}, 5.0).distance == Approx(std::sqrt(18.0)));
  CHECK_THROWS(WallDistance({Eigen::Matrix2Xd::Zero(2, 3)}));
}

TEST_CASE("wall layer: the boundary-layer tensors at any point, not only at coarse nodes",
          "[voronoi][sizes]") {
  // Wall y = 0, iso size 0.1, A = 100, T = 3: h_n = 0.1 (0.01 + 0.99 d / 0.3).
  const CartesianGrid coarse = CartesianGrid::spanning({0, 0}, {1, 1}, 11, 11);
  const MetricField iso(coarse, std::vector<Eigen::Matrix2d>(coarse.node_count(),
                                                             Eigen::Matrix2d::Identity() / 0.01));
  Eigen::Matrix2Xd wall(2, 101);
  for (int k = 0; k <= 100; ++k) wall.col(k) << -0.5 + 0.02 * k, 0.0;
  BoundaryLayerOptions o;
  o.wall_aspect = 100;
  o.thickness = 3;
  const MetricField bl = boundary_layer_metric(iso, {wall}, o);
  REQUIRE(bl.layer() != nullptr);
  CHECK(bl.anisotropy() == Approx(100));
  CHECK(bl.min_speed() == Approx(0.001));
  for (const double d : {0.0, 1e-4, 3e-3, 0.05, 0.2, 0.29, 0.5}) {
    const Eigen::Matrix2d M = bl.metric_at({0.43, d});
    const double hn = 0.1 * (0.01 + 0.99 * std::min(1.0, d / 0.3));
    CHECK(1 / std::sqrt(M(1, 1)) == Approx(hn).epsilon(1e-9));
    CHECK(1 / std::sqrt(M(0, 0)) == Approx(0.1).epsilon(1e-9));
    CHECK(std::abs(M(0, 1)) < 1e-9 * M(1, 1));
  }
  // At a coarse node the same tensor as the node's own (what the growth uses).
  const Eigen::Vector2d node = coarse.point(4, 1);
  CHECK((bl.metric_at(node) - bl.metric(coarse.index(4, 1))).norm() <
        1e-6 * bl.metric(coarse.index(4, 1)).norm());
}
