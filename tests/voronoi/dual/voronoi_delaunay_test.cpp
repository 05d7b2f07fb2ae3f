#include "voronoi/dual/voronoi_delaunay.h"

#include <Eigen/Cholesky>
#include <catch2/catch.hpp>
#include <cmath>
#include <set>

#include "../thesis_examples.h"
#include "../voronoi_test_support.h"

using namespace homesh;

namespace {

VoronoiProblem unit_square(int n, const Eigen::Matrix2Xd& seeds, const MetricField& metric) {
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({0, 0}, {1, 1}, n, n);
  p.seeds = seeds;
  p.metric = metric;
  return p;
}

}  // namespace

TEST_CASE("in a constant isotropic metric the dual is CGAL's Delaunay triangulation",
          "[voronoi][delaunay]") {
  const int n = 401;
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  for (const Eigen::Matrix2Xd& seeds : test::general_seed_sets(1, 20, 1.0 / (n - 1), I)) {
    const VoronoiDelaunay v = voronoi_delaunay(unit_square(n, seeds, MetricField::constant(I)));
    CHECK(v.valid());
    CHECK(test::rotated(v.dual.triangles) == test::delaunay_in_box(seeds, 0.0, 1.0).triangles);
    CHECK(v.check.inverted == 0);
    CHECK(v.check.euler == 1);
    CHECK(v.dual.unjoined_triples == 0);
    CHECK(v.dual.orientation_conflicts == 0);
    // Every region adjacency was found as a collision, but for Voronoi edges
    // shorter than the gaps between frozen fronts.
    CHECK(v.dual.adjacency_edges <= 1);
  }
}

TEST_CASE(
    "in a constant anisotropic metric the dual is the Delaunay triangulation of the "
    "mapped seeds",
    "[voronoi][delaunay]") {
  // With M = L L^T, |x|_M = |L^T x|: the metric Voronoi diagram is the
  // Euclidean one of the seeds mapped by L^T.
  const int n = 251;
  const Eigen::Matrix2d M = metric_from_axes(0.6, 1.0, 0.4);
  const Eigen::Matrix2d Lt = M.llt().matrixL().transpose();
  for (const Eigen::Matrix2Xd& seeds : test::general_seed_sets(1, 15, 1.0 / (n - 1), M)) {
    const VoronoiDelaunay v = voronoi_delaunay(unit_square(n, seeds, MetricField::constant(M)));
    CHECK(v.valid());
    const auto expected = test::delaunay_in_box(seeds, 0.0, 1.0, Lt).triangles;
    CHECK(test::rotated(v.dual.triangles) == expected);
    // Not the Euclidean triangulation: the metric matters here.
    CHECK(test::delaunay_in_box(seeds, 0.0, 1.0).triangles != expected);
  }
}

TEST_CASE("the five-seed example of Fig 2.2 under three metric fields", "[voronoi][delaunay]") {
  // (a) constant isotropic, (c) constant anisotropic, (e) variable
  // (thesis_examples.h), with both engines: the same duals.
  std::vector<std::vector<std::set<std::array<int, 3>>>> by_engine;
  for (const std::string engine : {"level_set", "fast_marching"}) {
    std::vector<std::set<std::array<int, 3>>>& duals = by_engine.emplace_back();
    for (int kind = 0; kind < 3; ++kind) {
      INFO(engine << ", metric field " << kind);
      const VoronoiProblem p = test::five_seeds(kind, 151).problem;
      const VoronoiDelaunay v = voronoi_delaunay(p, engine);
      CHECK(v.valid());
      CHECK(v.regions.regions.size() == 5);
      duals.push_back(test::rotated(v.dual.triangles));
      if (kind < 2) {
        const Eigen::Matrix2d Lt = p.metric.metric(0).llt().matrixL().transpose();
        CHECK(duals.back() == test::delaunay_in_box(p.seeds, 0.0, 1.0, Lt).triangles);
      }
    }
    // The centre seed joins all four others in the isotropic metric, not in
    // the constant anisotropic one.
    CHECK(duals[0] == std::set<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}});
    CHECK(duals[1] == std::set<std::array<int, 3>>{{0, 1, 2}, {0, 3, 4}, {0, 4, 1}});
  }
  CHECK(by_engine[0] == by_engine[1]);
}

TEST_CASE("crystals in a disc conform to its boundary, wet or dry", "[voronoi][delaunay]") {
  // A ring of seeds close to the boundary, a second ring, one centre seed.
  const int n = 201;
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({-1, -1}, {1, 1}, n, n);
  p.domain = sample_on_grid(p.grid, [](const Eigen::Vector2d& x) { return x.norm() - 0.9; });
  const int K = 24;
  p.seeds.resize(2, 2 * K + 1);
  for (int k = 0; k < K; ++k) {
    const double a = 2 * M_PI * k / K, b = 2 * M_PI * (k + 0.5) / K;
    p.seeds.col(k) = 0.87 * Eigen::Vector2d(std::cos(a), std::sin(a));
    p.seeds.col(K + k) = 0.6 * Eigen::Vector2d(std::cos(b), std::sin(b));
  }
  p.seeds.col(2 * K) = Eigen::Vector2d(0.03, -0.02);
  for (const Contact contact : {Contact::dry, Contact::wet}) {
    INFO((contact == Contact::dry ? "dry" : "wet"));
    p.contact = contact;
    const VoronoiDelaunay v = voronoi_delaunay(p);
    CHECK(v.valid());
    CHECK(v.regions.domain_euler == 1);
    CHECK(v.check.euler == 1);
    // Nodes outside the disc are in no crystal; the outer ring touched it.
    int outside_labelled = 0;
    for (int k = 0; k < p.grid.node_count(); ++k)
      outside_labelled += p.domain(k) > 0 && v.partition.labels(k) >= 0;
    CHECK(outside_labelled == 0);
    std::vector<int> outer(K);
    for (int k = 0; k < K; ++k) outer[k] = k;
    CHECK(v.partition.boundary_contacts == outer);
    // A fan of K triangles at the centre and 2K in the band between the
    // rings: F = 2V - 2 - (boundary vertices) for a triangulated disc.
    CHECK(v.dual.triangles.size() == 3 * K);
  }
}

TEST_CASE("the dual of an annulus has Euler characteristic 0", "[voronoi][delaunay]") {
  const int n = 201;
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({-1, -1}, {1, 1}, n, n);
  p.domain = sample_on_grid(
      p.grid, [](const Eigen::Vector2d& x) { return std::abs(x.norm() - 0.6) - 0.3; });
  const int K = 16;
  p.seeds.resize(2, 2 * K);
  for (int k = 0; k < K; ++k) {
    const double a = 2 * M_PI * k / K, b = 2 * M_PI * (k + 0.5) / K;
    p.seeds.col(k) = 0.45 * Eigen::Vector2d(std::cos(a), std::sin(a));
    p.seeds.col(K + k) = 0.75 * Eigen::Vector2d(std::cos(b), std::sin(b));
  }
  const VoronoiDelaunay v = voronoi_delaunay(p);
  CHECK(v.valid());
  CHECK(v.regions.domain_euler == 0);
  CHECK(v.check.euler == 0);
  CHECK(v.dual.triangles.size() == 2 * K);
}

TEST_CASE("crystals meeting inside a thin wall of the boundary are not neighbours",
          "[voronoi][delaunay]") {
  // A wall 3 cells thick across the square splits the domain in two: the
  // contact bands of the two sides overlap inside it.
  const int n = 101;
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({0, 0}, {1, 1}, n, n);
  p.domain = sample_on_grid(p.grid,
                            [](const Eigen::Vector2d& x) { return 0.015 - std::abs(x.y() - 0.5); });
  p.seeds.resize(2, 4);
  p.seeds << 0.3, 0.7, 0.4, 0.6,  //
      0.3, 0.25, 0.7, 0.75;
  for (const Contact contact : {Contact::dry, Contact::wet}) {
    p.contact = contact;
    const VoronoiDelaunay v = voronoi_delaunay(p);
    CHECK(v.valid());
    CHECK(v.regions.domain_euler == 2);
    CHECK(v.partition.collisions == std::vector<std::array<int, 2>>{{0, 1}, {2, 3}});
    CHECK(v.check.euler == 2);
  }
}
