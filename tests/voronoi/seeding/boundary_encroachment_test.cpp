#include "voronoi/seeding/boundary_encroachment.h"

#include <catch2/catch.hpp>

#include "voronoi/dual/refine_dual.h"
#include "voronoi/metric/metric_field.h"

using namespace homesh;

TEST_CASE("seeds inside a boundary segment's diametral circle encroach on it",
          "[voronoi][encroachment]") {
  // Boundary seeds 0, 1, 2 on the x-axis (segments 0-1, 1-2 of length 1),
  // interior seeds at 0.45 and 0.55 above the first segment's midpoint and
  // one outside the second's circle, at (1.9, 0.35): 0.532 from its centre.
  Eigen::Matrix2Xd seeds(2, 6);
  seeds << 0, 1, 2, 0.5, 0.5, 1.9,  //
      0, 0, 0, 0.45, 0.55, 0.35;
  const std::vector<std::array<int, 2>> segments = {{0, 1}, {1, 2}};
  CHECK(encroaching_seeds(seeds, 3, segments) == std::vector<int>{3});
  seeds(1, 5) = 0.2;  // (1.9, 0.2): 0.447 from (1.5, 0), inside radius 0.5
  CHECK(encroaching_seeds(seeds, 3, segments) == std::vector<int>{3, 5});
  CHECK(encroaching_seeds(seeds, 3, {}).empty());
}

TEST_CASE("encroaching seeds in an anisotropic metric: its diametral ellipse",
          "[voronoi][seeding]") {
  // Segment (0, 0) - (1, 0); a seed at (0.5, 0.3) is in its Euclidean
  // diametral circle, but with sizes 1 along x and 0.1 across (M = diag(1,
  // 100)) the angle at it is acute: (x - a)^T M (x - b) = -0.25 + 9 > 0.
  Eigen::Matrix2Xd seeds(2, 4);
  seeds << 0, 1, 0.5, 0.5,  //
      0, 0, 0.3, 0.03;
  const std::vector<std::array<int, 2>> segments = {{0, 1}};
  CHECK(homesh::encroaching_seeds(seeds, 2, segments) == std::vector<int>{2, 3});
  const homesh::MetricField metric =
      homesh::MetricField::constant(Eigen::Vector2d(1, 100).asDiagonal());
  // (0.5, 0.03): -0.25 + 0.09 < 0, inside the ellipse too.
  CHECK(homesh::encroaching_seeds(seeds, 2, segments, &metric) == std::vector<int>{3});
}
