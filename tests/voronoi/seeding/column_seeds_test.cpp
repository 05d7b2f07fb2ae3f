#include "voronoi/seeding/column_seeds.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "voronoi/metric/size_metric.h"

using namespace homesh;

namespace {

// The unit square's boundary, 0.1 apart, counter-clockwise (the domain on
// the left), and a boundary-layer metric on its bottom side y = 0.
struct Square {
  Eigen::Matrix2Xd seeds{2, 40};
  std::vector<std::array<int, 2>> segments;
  Square() {
    for (int k = 0; k < 10; ++k) {
      seeds.col(k) << 0.1 * k, 0;
      seeds.col(10 + k) << 1, 0.1 * k;
      seeds.col(20 + k) << 1 - 0.1 * k, 1;
      seeds.col(30 + k) << 0, 1 - 0.1 * k;
    }
    for (int k = 0; k < 40; ++k) segments.push_back({k, (k + 1) % 40});
  }
};

MetricField bottom_layer(double aspect) {
  const CartesianGrid coarse = CartesianGrid::spanning({0, 0}, {1, 1}, 11, 11);
  const MetricField iso(coarse, std::vector<Eigen::Matrix2d>(coarse.node_count(),
                                                             Eigen::Matrix2d::Identity() / 0.01));
  Eigen::Matrix2Xd wall(2, 101);
  for (int k = 0; k <= 100; ++k) wall.col(k) << 0.01 * k, 0.0;
  BoundaryLayerOptions o;
  o.wall_aspect = aspect;
  o.thickness = 3;
  return boundary_layer_metric(iso, {wall}, o);
}

}  // namespace

TEST_CASE("column seeds: unit steps of the metric across the wall, up to where it relaxes",
          "[voronoi][seeding]") {
  const Square sq;
  const CartesianGrid grid = CartesianGrid::spanning({0, 0}, {1, 1}, 201, 201);
  const MetricField metric = bottom_layer(100);
  const ColumnSeeds c = metric_column_seeds(grid, {}, metric, sq.seeds, sq.segments);
  // Columns on the bottom's 9 seeds between its corners; none on the other
  // sides (isotropic there) or at the corners.
  CHECK(c.columns == 9);
  // h_n = 0.1 (0.01 + 0.99 d / 0.3); the column ends where h / h_n < 1.5,
  // after about (T / (1 - 1/A)) ln(A / 1.5) = 12.7 unit steps.
  CHECK(c.rows >= 12);
  CHECK(c.rows <= 13);
  REQUIRE(c.seeds.cols() == 9 * c.rows);
  // Row by row: each on its wall seed's normal, each step one unit of the
  // metric at its midpoint (within the fixed point's 1 %).
  for (int col = 0; col < 9; ++col) {
    double y = 0;
    for (int row = 0; row < c.rows; ++row) {
      const Eigen::Vector2d q = c.seeds.col(9 * row + col);
      CHECK(q.x() == Approx(0.1 * (col + 1)).margin(1e-12));
      const double mid = 0.5 * (y + q.y());
      const double hn = 0.1 * (0.01 + 0.99 * std::min(1.0, mid / 0.3));
      CHECK((q.y() - y) / hn == Approx(1.0).epsilon(0.01));
      y = q.y();
    }
  }
  // The first seed: a unit step in the metric at its midpoint, h = h_n(h / 2)
  // = 0.001 + 0.165 h, so h = 0.001 / 0.835 (not the wall's 0.001).
  CHECK(c.seeds(1, 0) == Approx(0.001 / 0.835).epsilon(0.01));
  // No columns where the metric is isotropic; none with the option off.
  CHECK(metric_column_seeds(grid, {}, bottom_layer(1), sq.seeds, sq.segments).columns == 0);
  SeedingOptions off;
  off.column_anisotropy = 0;
  CHECK(metric_column_seeds(grid, {}, metric, sq.seeds, sq.segments, off).seeds.cols() == 0);
}
