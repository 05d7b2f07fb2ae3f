#include "voronoi/metric_seeding.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "voronoi/loop_distance.h"

using namespace homesh;

TEST_CASE("Poisson-disc seeds follow the metric", "[voronoi][seeding]") {
  // The unit square, size 0.05 isotropic, then 0.1 along x by 0.02 along y.
  const CartesianGrid g = CartesianGrid::spanning({0, 0}, {1, 1}, 201, 201);
  Eigen::Matrix2Xd square(2, 4);
  square << 0, 1, 1, 0,  //
      0, 0, 1, 1;
  const Eigen::VectorXd domain = loop_signed_distance(g, {square}, 0.1);
  for (const auto& [hx, hy] : {std::pair<double, double>{0.05, 0.05}, {0.1, 0.02}}) {
    INFO("sizes " << hx << " by " << hy);
    const Eigen::Matrix2d M = metric_from_axes(0.0, hx, hy);
    const SeedingOptions o;
    const Eigen::Matrix2Xd s =
        metric_interior_seeds(g, domain, MetricField::constant(M), Eigen::Matrix2Xd(2, 0), o);
    // Spacing at least o.spacing in the metric, o.boundary_gap from the walls.
    double closest = 1e300;
    for (int a = 0; a < s.cols(); ++a) {
      const Eigen::Vector2d p = s.col(a);
      CHECK(std::min(p.x(), 1 - p.x()) / hx >= o.boundary_gap - 1e-9);
      CHECK(std::min(p.y(), 1 - p.y()) / hy >= o.boundary_gap - 1e-9);
      for (int b = a + 1; b < s.cols(); ++b) {
        const Eigen::Vector2d v = s.col(b) - p;
        closest = std::min(closest, std::sqrt(v.dot(M * v)));
      }
    }
    CHECK(closest >= o.spacing - 1e-9);
    // Maximal: the metric area per seed, in the square less the boundary gap,
    // is that of a disc packing of this spacing, 0.6 to 1.5 times spacing^2.
    const double gap_x = 2 * o.boundary_gap * hx, gap_y = 2 * o.boundary_gap * hy;
    const double per_seed = (1 - gap_x) * (1 - gap_y) / (hx * hy) / static_cast<double>(s.cols());
    CHECK(per_seed > 0.6 * o.spacing * o.spacing);
    CHECK(per_seed < 1.5 * o.spacing * o.spacing);
  }
}
