#include "voronoi/seeding/metric_seeding.h"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "voronoi/cleanup/metric_smoothing.h"
#include "voronoi/grid/loop_distance.h"

using namespace homesh;

namespace {

// The interior seeds of the unit square in the constant metric M, with no
// boundary seeds (they grow from its deepest grid node).
Eigen::Matrix2Xd square_seeds(const Eigen::Matrix2d& M, const SeedingOptions& o) {
  const CartesianGrid g = CartesianGrid::spanning({0, 0}, {1, 1}, 201, 201);
  Eigen::Matrix2Xd square(2, 4);
  square << 0, 1, 1, 0,  //
      0, 0, 1, 1;
  return metric_interior_seeds(g, loop_signed_distance(g, {square}, 0.1), MetricField::constant(M),
                               Eigen::Matrix2Xd(2, 0), o);
}

// The metric distances from seed a of s to every other seed.
std::vector<double> distances_from(const Eigen::Matrix2Xd& s, int a, const Eigen::Matrix2d& M) {
  std::vector<double> out;
  for (int b = 0; b < s.cols(); ++b) {
    const Eigen::Vector2d v = s.col(b) - s.col(a);
    if (b != a) out.push_back(std::sqrt(v.dot(M * v)));
  }
  return out;
}

}  // namespace

TEST_CASE("Poisson-disc seeds follow the metric", "[voronoi][seeding]") {
  // The unit square, size 0.05 isotropic, then 0.1 along x by 0.02 along y.
  for (const auto& [hx, hy] : {std::pair<double, double>{0.05, 0.05}, {0.1, 0.02}})
    for (const std::string interior : {"lattice", "poisson"}) {
      INFO("sizes " << hx << " by " << hy << ", interior " << interior);
      const Eigen::Matrix2d M = metric_from_axes(0.0, hx, hy);
      SeedingOptions o;
      o.interior = interior;
      const Eigen::Matrix2Xd s = square_seeds(M, o);
      // Spacing at least o.spacing in the metric, o.boundary_gap from the walls.
      double closest = 1e300;
      for (int a = 0; a < s.cols(); ++a) {
        const Eigen::Vector2d p = s.col(a);
        CHECK(std::min(p.x(), 1 - p.x()) / hx >= o.boundary_gap - 1e-9);
        CHECK(std::min(p.y(), 1 - p.y()) / hy >= o.boundary_gap - 1e-9);
        for (const double d : distances_from(s, a, M)) closest = std::min(closest, d);
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

TEST_CASE("lattice seeds: hexagonal in an isotropic metric, Poisson-disc in an anisotropic one",
          "[voronoi][seeding]") {
  // The unit square, sizes 0.04 isotropic, then 0.08 by 0.02 turned by 30
  // degrees; no boundary seeds, so the lattice grows from one seed.
  // The share of seeds with six others at unit metric distance (1e-9).
  const auto hexagonal_share = [](const Eigen::Matrix2d& M, const std::string& interior) {
    SeedingOptions o;
    o.interior = interior;
    const Eigen::Matrix2Xd s = square_seeds(M, o);
    int hexagonal = 0;
    for (int a = 0; a < s.cols(); ++a) {
      const std::vector<double> d = distances_from(s, a, M);
      hexagonal +=
          std::count_if(d.begin(), d.end(), [](double x) { return std::abs(x - 1) < 1e-9; }) == 6;
    }
    return static_cast<double>(hexagonal) / static_cast<double>(s.cols());
  };
  const Eigen::Matrix2d iso = metric_from_axes(M_PI / 6, 0.04, 0.04);
  // Only the seeds within a size of the walls, and the Poisson-disc ones in
  // the gaps there, miss neighbours (measured 0.85).
  CHECK(hexagonal_share(iso, "lattice") > 0.7);
  CHECK(hexagonal_share(iso, "poisson") < 0.01);
  // Anisotropic: Poisson-disc seeds either way (the lattice made slivers
  // above metric=bl layers).
  const Eigen::Matrix2d aniso = metric_from_axes(M_PI / 6, 0.08, 0.02);
  CHECK(hexagonal_share(aniso, "lattice") < 0.01);
}

TEST_CASE("interior seeds: an unknown kind is an error", "[voronoi][seeding]") {
  const CartesianGrid g = CartesianGrid::spanning({0, 0}, {1, 1}, 11, 11);
  SeedingOptions o;
  o.interior = "hexagonal";
  CHECK_THROWS_WITH(metric_interior_seeds(g, Eigen::VectorXd(),
                                          MetricField::constant(Eigen::Matrix2d::Identity()),
                                          Eigen::Matrix2Xd(2, 0), o),
                    Catch::Contains("interior 'hexagonal'"));
}

namespace {

// The unit square's boundary divided into n segments per side,
// counter-clockwise from (0, 0) (the domain on the left), as seeds and
// segments; `grid` and `domain` over it.
struct SquareBoundary {
  Eigen::Matrix2Xd seeds;
  std::vector<std::array<int, 2>> segments;
  CartesianGrid grid = CartesianGrid::spanning({0, 0}, {1, 1}, 201, 201);
  Eigen::VectorXd domain;
  SquareBoundary(int nx, int ny) : seeds(2, 2 * (nx + ny)) {
    Eigen::Matrix2Xd square(2, 4);
    square << 0, 1, 1, 0,  //
        0, 0, 1, 1;
    domain = loop_signed_distance(grid, {square}, 0.1);
    int k = 0;
    for (int i = 0; i < nx; ++i) seeds.col(k++) << double(i) / nx, 0;
    for (int j = 0; j < ny; ++j) seeds.col(k++) << 1, double(j) / ny;
    for (int i = 0; i < nx; ++i) seeds.col(k++) << 1 - double(i) / nx, 1;
    for (int j = 0; j < ny; ++j) seeds.col(k++) << 0, 1 - double(j) / ny;
    for (int s = 0; s < k; ++s) segments.push_back({s, (s + 1) % k});
  }
};

double metric_distance(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                       const Eigen::Matrix2d& M) {
  return std::sqrt((b - a).dot(M * (b - a)));
}

}  // namespace

TEST_CASE(
    "front seeds: a row of equilateral apexes on straight walls, a seed splitting each "
    "right-angled corner",
    "[voronoi][seeding]") {
  // Size 0.1, 10 unit segments per side.
  const SquareBoundary b(10, 10);
  const Eigen::Matrix2d M = Eigen::Matrix2d::Identity() / 0.01;
  SeedingOptions o;
  o.front_rows = 1;
  const FrontSeeds f =
      metric_front_seeds(b.grid, b.domain, MetricField::constant(M), b.seeds, b.segments, o);
  // 4 corner seeds, then on each side the apexes of segments 2 to 9: those of
  // the end segments lie within the corner seed's spacing and 0.05 from the
  // other wall.
  REQUIRE(f.seeds.cols() == 4 + 4 * 8);
  CHECK(f.first_row == f.seeds.cols());
  const Eigen::Vector2d corners[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int c = 0; c < 4; ++c) {
    // On the diagonal, 0.1 from the corner: two triangles of 45 degrees at
    // the corner, mean ratio 0.947, where one right triangle has 0.866.
    const Eigen::Vector2d s = f.seeds.col(c);
    CHECK((s - corners[c]).norm() == Approx(0.1));
    CHECK(std::abs(s.x() - corners[c].x()) == Approx(std::abs(s.y() - corners[c].y())));
    const Eigen::Vector2d along = corners[(c + 1) % 4] - corners[c];
    CHECK(metric_mean_ratio(corners[c], corners[c] + 0.1 * along, s, M) ==
          Approx(0.9473).epsilon(1e-3));
  }
  for (int k = 4; k < f.seeds.cols(); ++k) {
    const Eigen::Vector2d q = f.seeds.col(k);
    // The apex of the segment below it: sqrt(3)/2 0.1 from its wall, above a midpoint.
    const double wall = std::min({q.x(), q.y(), 1 - q.x(), 1 - q.y()});
    CHECK(wall == Approx(std::sqrt(3.0) / 2 * 0.1));
    const double along = wall == Approx(q.y()) || wall == Approx(1 - q.y()) ? q.x() : q.y();
    CHECK(std::fmod(along + 1e-9, 0.1) == Approx(0.05).margin(1e-6));
  }
  // No two seeds closer than front_spacing in the metric, none within it of a boundary seed.
  for (int a = 0; a < f.seeds.cols(); ++a) {
    for (int c = a + 1; c < f.seeds.cols(); ++c)
      CHECK(metric_distance(f.seeds.col(a), f.seeds.col(c), M) >= o.front_spacing);
    for (int c = 0; c < b.seeds.cols(); ++c)
      CHECK(metric_distance(f.seeds.col(a), b.seeds.col(c), M) >= o.front_spacing);
  }
}

TEST_CASE("front seeds: rows advance on the hexagonal lattice of the walls", "[voronoi][seeding]") {
  const SquareBoundary b(20, 20);  // size 0.05
  const Eigen::Matrix2d M = Eigen::Matrix2d::Identity() / 0.0025;
  SeedingOptions o;
  o.front_rows = 4;
  const FrontSeeds f =
      metric_front_seeds(b.grid, b.domain, MetricField::constant(M), b.seeds, b.segments, o);
  CHECK(f.first_row < f.seeds.cols());
  // Away from the corners and the other walls, the seeds the bottom wall
  // grows are the lattice x = 0.025 k, y = h r with h = sqrt(3)/2 0.05 and k
  // of the parity of r: every row up to the fourth, equilateral rows.
  const double h = std::sqrt(3.0) / 2 * 0.05;
  int on_rows[5] = {0, 0, 0, 0, 0};
  for (int k = 0; k < f.seeds.cols(); ++k) {
    const Eigen::Vector2d q = f.seeds.col(k);
    if (q.x() < 0.35 || q.x() > 0.65 || q.y() > 0.3) continue;
    const double r = q.y() / h, i = q.x() / 0.025;
    CHECK(r == Approx(std::round(r)).margin(1e-6));
    CHECK(i == Approx(std::round(i)).margin(1e-6));
    CHECK((std::lround(r) + std::lround(i)) % 2 == 0);
    if (std::lround(r) <= 4) ++on_rows[std::lround(r)];
  }
  // Rows of 0.3 / 0.05 = 6 seeds each (x in [0.35, 0.65] holds 6 of one parity).
  for (int r = 1; r <= 4; ++r) CHECK(on_rows[r] >= 6);
  CHECK(on_rows[0] == 0);
}

TEST_CASE("front seeds: the apex is unit in an anisotropic metric and in a graded one",
          "[voronoi][seeding]") {
  SECTION("anisotropic: equilateral in M") {
    // Sizes 0.1 along x, 0.02 along y: 10 unit segments along x, 50 along y.
    const SquareBoundary b(10, 50);
    const Eigen::Matrix2d M = metric_from_axes(0.0, 0.1, 0.02);
    SeedingOptions o;
    o.front_rows = 1;
    const FrontSeeds f =
        metric_front_seeds(b.grid, b.domain, MetricField::constant(M), b.seeds, b.segments, o);
    int bottom = 0;
    for (int k = 0; k < f.seeds.cols(); ++k) {
      const Eigen::Vector2d q = f.seeds.col(k);
      if (q.y() > 0.05 || q.x() < 0.2 || q.x() > 0.8) continue;
      ++bottom;
      const Eigen::Vector2d a(std::floor(q.x() / 0.1) * 0.1, 0), c = a + Eigen::Vector2d(0.1, 0);
      CHECK(metric_mean_ratio(a, c, q, M) == Approx(1.0));
    }
    CHECK(bottom == 6);
  }
  SECTION("graded: sides of unit length in the metric at the apex") {
    // h(y) = 0.05 (1 + 2 y), isotropic, on a coarse grid; the bottom wall
    // divided at 0.05. The apex sits where h is larger, so it lies above the
    // equilateral height and its sides are unit in M(q), not in M(wall).
    const SquareBoundary b(20, 20);
    const CartesianGrid coarse = CartesianGrid::spanning({0, 0}, {1, 1}, 11, 41);
    std::vector<Eigen::Matrix2d> Ms;
    for (int k = 0; k < coarse.node_count(); ++k) {
      const double y = coarse.point(k % coarse.nx, k / coarse.nx).y();
      Ms.push_back(Eigen::Matrix2d::Identity() / std::pow(0.05 * (1 + 2 * y), 2));
    }
    const MetricField metric(coarse, Ms);
    SeedingOptions o;
    o.front_rows = 1;
    const FrontSeeds f = metric_front_seeds(b.grid, b.domain, metric, b.seeds, b.segments, o);
    int bottom = 0;
    for (int k = 0; k < f.seeds.cols(); ++k) {
      const Eigen::Vector2d q = f.seeds.col(k);
      if (q.y() > 0.1 || q.x() < 0.2 || q.x() > 0.8) continue;
      ++bottom;
      const Eigen::Vector2d a(std::floor(q.x() / 0.05) * 0.05, 0);
      CHECK(metric_distance(a, q, metric.metric_at(q)) == Approx(1.0).epsilon(2e-3));
      CHECK(q.y() > 1.02 * std::sqrt(3.0) / 2 * 0.05);
    }
    CHECK(bottom == 12);
  }
}
