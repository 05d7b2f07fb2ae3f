#include "voronoi/dual/dual_triangulation.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "../voronoi_test_support.h"
#include "voronoi/dual/check_dual.h"
#include "voronoi/dual/region_analysis.h"

using namespace homesh;

namespace {

// The exact Voronoi labels of the grid nodes: the nearest seed.
Eigen::VectorXi nearest_seed_labels(const CartesianGrid& g, const Eigen::Matrix2Xd& seeds) {
  Eigen::VectorXi labels(g.node_count());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      Eigen::Index k;
      (seeds.colwise() - g.point(i, j)).colwise().squaredNorm().minCoeff(&k);
      labels(g.index(i, j)) = static_cast<int>(k);
    }
  return labels;
}

const MetricField kEuclid = MetricField::constant(Eigen::Matrix2d::Identity());

}  // namespace

TEST_CASE("the dual of exact Voronoi labels is CGAL's Delaunay triangulation", "[voronoi][dual]") {
  const int n = 301;
  const double ds = 1.0 / (n - 1);
  const CartesianGrid g = CartesianGrid::spanning({0, 0}, {1, 1}, n, n);
  int sets = 0;
  for (unsigned seed = 1; sets < 3; ++seed) {
    const Eigen::Matrix2Xd seeds = test::uniform_seeds(25, seed, 0.0, 1.0);
    const test::DelaunayInBox expected = test::delaunay_in_box(seeds, 0.0, 1.0);
    // General position at this resolution: no four seeds within 2 cells of
    // cocircular, no Voronoi vertex within 4 cells of the border.
    if (expected.incircle_margin < 2 * ds || expected.border_margin < 4 * ds) continue;
    ++sets;
    INFO("seed set " << seed);
    const Eigen::VectorXi labels = nearest_seed_labels(g, seeds);
    const RegionReport regions = analyse_regions(g, labels, seeds, {});
    const DualTriangulation dual =
        dual_triangulation(g, labels, seeds, {}, regions.adjacent, kEuclid);
    CHECK(test::rotated(dual.triangles) == expected.triangles);
    CHECK(dual.unjoined_triples == 0);
    CHECK(dual.orientation_conflicts == 0);
    CHECK(dual.defects.cols() == 0);
    // Each triangle's Voronoi vertex is read within a cell of its circumcentre.
    REQUIRE(dual.vertices.cols() == static_cast<int>(dual.triangles.size()));
    for (std::size_t f = 0; f < dual.triangles.size(); ++f) {
      const auto& t = dual.triangles[f];
      const Eigen::Vector2d c =
          test::circumcentre(seeds.col(t[0]), seeds.col(t[1]), seeds.col(t[2]));
      CHECK((dual.vertices.col(f) - c).norm() < ds);
    }
    const DualCheck check = check_dual(seeds, dual, regions);
    CHECK(check.bad_triangles.empty());
    CHECK(check.lone_edges.empty());
    CHECK(check.ok());
    CHECK(check.euler == 1);
    CHECK(check.inverted == 0);
  }
}

TEST_CASE(
    "a 4-label cell is split by the collided diagonal, else by the in-circle test "
    "in the local metric",
    "[voronoi][dual]") {
  // Regions 0, 1, 2, 3 counter-clockwise round the centre cell of a 10 x 10
  // grid: seeds of a rhombus, short diagonal 1-3 (vertical).
  const CartesianGrid g = CartesianGrid::spanning({0, 0}, {1, 1}, 10, 10);
  Eigen::Matrix2Xd seeds(2, 4);
  seeds << 0.8, 0.5, 0.2, 0.5,  //
      0.5, 0.7, 0.5, 0.3;
  Eigen::VectorXi labels(g.node_count());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const Eigen::Vector2d d = g.point(i, j) - Eigen::Vector2d(0.5, 0.5);
      const double a = std::atan2(d.y(), d.x());  // sectors centred on the seeds
      labels(g.index(i, j)) = static_cast<int>(std::floor((a + M_PI / 4) / (M_PI / 2)) + 4) % 4;
    }
  const std::vector<std::array<int, 2>> ring{{0, 1}, {1, 2}, {2, 3}, {0, 3}};

  const DualTriangulation iso = dual_triangulation(g, labels, seeds, ring, {}, kEuclid);
  CHECK(iso.quad_cells == 1);
  CHECK(test::rotated(iso.triangles) == std::set<std::array<int, 3>>{{0, 1, 3}, {1, 2, 3}});
  CHECK(iso.added_edges == std::vector<std::array<int, 2>>{{1, 3}});

  // Lengths along y tripled: the diagonal 0-2 is now the shorter.
  const MetricField stretched = MetricField::constant(metric_from_axes(0.0, 1.0, 1.0 / 3));
  const DualTriangulation aniso = dual_triangulation(g, labels, seeds, ring, {}, stretched);
  CHECK(test::rotated(aniso.triangles) == std::set<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}});

  // A collided diagonal wins over the in-circle test; of two collided ones
  // the in-circle test keeps one and drops the other.
  std::vector<std::array<int, 2>> with_02 = ring;
  with_02.push_back({0, 2});
  const DualTriangulation forced = dual_triangulation(g, labels, seeds, with_02, {}, kEuclid);
  CHECK(test::rotated(forced.triangles) == std::set<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}});
  CHECK(forced.added_edges.empty());
  std::vector<std::array<int, 2>> both = with_02;
  both.push_back({1, 3});
  const DualTriangulation dropped = dual_triangulation(g, labels, seeds, both, {}, kEuclid);
  CHECK(dropped.dropped_edges == std::vector<std::array<int, 2>>{{0, 2}});
  CHECK(dropped.edges.size() == 5);

  const RegionReport regions = analyse_regions(g, labels, seeds, {});
  CHECK(check_dual(seeds, iso, regions).ok());
  CHECK(check_dual(seeds, aniso, regions).ok());
}

TEST_CASE("check_dual finds missing and inverted triangles", "[voronoi][dual]") {
  const int n = 201;
  const CartesianGrid g = CartesianGrid::spanning({0, 0}, {1, 1}, n, n);
  Eigen::Matrix2Xd seeds(2, 5);
  seeds << 0.5, 0.2, 0.8, 0.75, 0.25,  //
      0.5, 0.25, 0.2, 0.8, 0.75;
  const Eigen::VectorXi labels = nearest_seed_labels(g, seeds);
  const RegionReport regions = analyse_regions(g, labels, seeds, {});
  DualTriangulation dual = dual_triangulation(g, labels, seeds, {}, regions.adjacent, kEuclid);
  REQUIRE(dual.triangles.size() == 4);
  REQUIRE(check_dual(seeds, dual, regions).ok());

  DualTriangulation missing = dual;
  missing.triangles.pop_back();
  const DualCheck m = check_dual(seeds, missing, regions);
  CHECK_FALSE(m.ok());
  CHECK(m.euler == 0);
  CHECK(m.bad_interior_edges == 2);
  // The two triangles sharing the now-lonely edges are at fault.
  CHECK(m.bad_triangles.size() == 2);
  CHECK(m.lone_edges.empty());

  DualTriangulation flipped = dual;
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  const DualCheck f = check_dual(seeds, flipped, regions);
  CHECK(f.inverted == 1);
  CHECK_FALSE(f.ok());
  CHECK(std::count(f.bad_triangles.begin(), f.bad_triangles.end(), 0) == 1);

  DualTriangulation none = dual;
  none.triangles.clear();
  const DualCheck z = check_dual(seeds, none, regions);
  CHECK(z.lone_edges.size() == 4);  // the spokes from the centre seed
}

TEST_CASE("analyse_regions: orphans, isolated regions, domain topology", "[voronoi][regions]") {
  const int n = 41;
  const CartesianGrid g = CartesianGrid::spanning({-1, -1}, {1, 1}, n, n);
  // Four quadrant regions; a blob of label 3 inside quadrant 0 (an orphan),
  // and a seed 4 whose region is a blob inside quadrant 1 (isolated).
  Eigen::Matrix2Xd seeds(2, 5);
  seeds << 0.5, -0.8, -0.5, 0.5, -0.4,  //
      0.5, 0.8, -0.5, -0.5, 0.4;
  Eigen::VectorXi labels(g.node_count());
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d x = g.point(i, j);
      int l = x.y() >= 0 ? (x.x() >= 0 ? 0 : 1) : (x.x() < 0 ? 2 : 3);
      if ((x - Eigen::Vector2d(0.7, 0.25)).norm() < 0.15) l = 3;
      if ((x - seeds.col(4)).norm() < 0.2) l = 4;
      labels(g.index(i, j)) = l;
    }
  const RegionReport r = analyse_regions(g, labels, seeds, {});
  CHECK(r.regions.size() == 6);
  REQUIRE(r.orphans.size() == 1);
  CHECK(r.regions[r.orphans[0]].label == 3);
  CHECK(r.regions[r.orphans[0]].neighbours == std::vector<int>{0});
  CHECK_FALSE(r.regions[r.orphans[0]].touches_boundary);
  CHECK(r.isolated == std::vector<int>{4});
  CHECK(r.missing.empty());
  CHECK(r.domain_euler == 1);
  // The 4 quadrant pairs (0-3 also round the orphan) and 1-4.
  CHECK(r.adjacent == std::vector<std::array<int, 2>>{{0, 1}, {0, 3}, {1, 2}, {1, 4}, {2, 3}});

  // Domain topology from the level set: disc 1, annulus 0, two discs 2.
  const auto euler = [&](auto&& level_set) {
    return analyse_regions(g, Eigen::VectorXi::Zero(g.node_count()), Eigen::Matrix2Xd::Zero(2, 1),
                           sample_on_grid(g, level_set))
        .domain_euler;
  };
  CHECK(euler([](const Eigen::Vector2d& x) { return x.norm() - 0.8; }) == 1);
  CHECK(euler([](const Eigen::Vector2d& x) { return std::abs(x.norm() - 0.6) - 0.25; }) == 0);
  CHECK(euler([](const Eigen::Vector2d& x) {
          return std::min((x - Eigen::Vector2d(0.5, 0)).norm(),
                          (x + Eigen::Vector2d(0.5, 0)).norm()) -
                 0.3;
        }) == 2);
}
