#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "../voronoi_test_support.h"
#include "core/error.h"
#include "voronoi/dual/voronoi_delaunay.h"
#include "voronoi/engines/fast_marching_engine.h"
#include "voronoi/engines/label_contacts.h"
#include "voronoi/engines/lattice_stencil.h"
#include "voronoi/engines/morton_order.h"
#include "voronoi/engines/stencil_field.h"
#include "voronoi/engines/voronoi_engines.h"

using namespace homesh;

namespace {

VoronoiProblem unit_square(int n, const Eigen::Matrix2Xd& seeds, const Eigen::Matrix2d& M) {
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({0, 0}, {1, 1}, n, n);
  p.seeds = seeds;
  p.metric = MetricField::constant(M);
  return p;
}

// Mislabelled nodes against the exact Voronoi diagram of the metric distance
// |x - p|_M: their fraction, and the largest Euclidean distance, in cells, of
// one to the bisector of its exact seed and its label.
struct LabelErrors {
  double fraction = 0.0;
  double worst_cells = 0.0;
};

LabelErrors label_errors(const CartesianGrid& g, const Eigen::VectorXi& labels,
                         const Eigen::Matrix2Xd& seeds, const Eigen::Matrix2d& M) {
  LabelErrors out;
  int wrong = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const Eigen::Vector2d x = g.point(i, j);
      int s = 0;
      double best = 1e300;
      for (int q = 0; q < seeds.cols(); ++q) {
        const Eigen::Vector2d v = x - seeds.col(q);
        if (v.dot(M * v) < best) best = v.dot(M * v), s = q;
      }
      const int k = labels(g.index(i, j));
      if (k == s) continue;
      ++wrong;
      const Eigen::Vector2d ps = seeds.col(s), pk = seeds.col(k);
      const Eigen::Vector2d n = M * (pk - ps);
      const double c = (pk.dot(M * pk) - ps.dot(M * ps)) / 2;
      out.worst_cells = std::max(out.worst_cells, std::abs(n.dot(x) - c) / n.norm() / g.ds());
    }
  out.fraction = static_cast<double>(wrong) / g.node_count();
  return out;
}

// The crystals of p grown by fast marching: settled, every node covered, under
// 0.1 % of the nodes mislabelled against the exact metric Voronoi diagram of
// the seeds (metric M) and none more than half a cell from its bisector.
CrystalPartition check_labels(const VoronoiProblem& p, const Eigen::Matrix2Xd& seeds,
                              const Eigen::Matrix2d& M) {
  const CrystalPartition r = grow_crystals(p, "fast_marching");
  CHECK(r.settled);
  CHECK(r.uncovered == 0);
  const LabelErrors e = label_errors(p.grid, r.labels, seeds, M);
  CHECK(e.fraction < 0.001);
  CHECK(e.worst_cells <= 0.5);
  return r;
}

}  // namespace

TEST_CASE("the lattice stencil is an M-obtuse superbase at any anisotropy", "[voronoi][fmm]") {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> angle(0.0, M_PI), aspect(0.0, 3.0);
  const Eigen::Vector2d h(0.01, 0.02);
  for (int trial = 0; trial < 200; ++trial) {
    const double ratio = std::pow(10.0, aspect(gen));
    const double theta = angle(gen);
    const Eigen::Matrix2d M = metric_from_axes(theta, 1.0, 1.0 / ratio);
    // From scratch, and warm-started from the stencil of a metric turned a
    // little (its superbase nearly always kept) and of an unrelated one.
    const LatticeStencil near =
        lattice_stencil(metric_from_axes(theta + 0.01, 1.0, 1.0 / ratio), h.x(), h.y());
    const LatticeStencil far =
        lattice_stencil(metric_from_axes(theta + 1.5, 1.0, 1.0), h.x(), h.y());
    for (const LatticeStencil& st :
         {lattice_stencil(M, h.x(), h.y()), lattice_stencil(M, h.x(), h.y(), near),
          lattice_stencil(M, h.x(), h.y(), far)}) {
      for (int k = 0; k < 6; ++k) {
        const Eigen::Vector2i u = st.offset(k), v = st.offset((k + 1) % 6);
        const Eigen::Vector2d U = u.cast<double>().cwiseProduct(h),
                              V = v.cast<double>().cwiseProduct(h);
        // Unimodular counter-clockwise sectors with M-acute angles.
        CHECK(u.x() * v.y() - u.y() * v.x() == 1);
        CHECK(U.dot(M * V) >= -1e-12 * st.length(k) * st.length(k));
        // The grid-unit lengths and sector constants are the physical ones.
        CHECK(st.length(k) == Approx(std::sqrt(U.dot(M * U))));
        const SectorConstants c = st.sector(k);
        const Eigen::Vector2d W = V - U;
        CHECK(c.A == Approx(U.dot(M * U)));
        CHECK(c.B == Approx(U.dot(M * W)).margin(1e-12 * c.A));
        CHECK(c.C == Approx(W.dot(M * W)));
        CHECK(c.det == Approx(c.A * c.C - c.B * c.B).epsilon(1e-6));
      }
      CHECK((st.offset(0) + st.offset(2) + st.offset(4)).isZero());
      // Any grid vector's length, through its coordinates in the superbase.
      const Eigen::Vector2d r = Eigen::Vector2d(3.5, -7.25).cwiseProduct(h);
      CHECK(st.norm2(Eigen::Vector2d(3.5, -7.25)) == Approx(r.dot(M * r)));
    }
  }
}

TEST_CASE("the Hopf-Lax sector update is exact for a plane wave", "[voronoi][fmm]") {
  // T(x) = g . x with |g|_{M^-1} = 1 is a metric distance to a line; the
  // update from the sector holding the characteristic -M^-1 g returns it.
  const Eigen::Matrix2d M = metric_from_axes(0.4, 1.0, 0.1);
  const LatticeStencil st = lattice_stencil(M, 0.01, 0.01);
  const auto vec = [&](int k) { return Eigen::Vector2d(0.01 * st.offset(k % 6).cast<double>()); };
  int exact = 0;
  for (int m = 0; m < 64; ++m) {
    const Eigen::Vector2d dir(std::cos(m * M_PI / 32), std::sin(m * M_PI / 32));
    const Eigen::Vector2d g = dir / std::sqrt(dir.dot(M.inverse() * dir));
    for (int k = 0; k < 6; ++k) {
      const double a = g.dot(vec(k)), b = g.dot(vec(k + 1));
      const double t = hopf_lax(st.sector(k), a, b);
      // Characteristic in the sector: the update must find T(x) = 0.
      const Eigen::Vector2d c = -(M.inverse() * g);
      Eigen::Matrix2d B;
      B << vec(k), vec(k + 1);
      const Eigen::Vector2d w = B.inverse() * c;
      if (w.minCoeff() > 1e-9) {
        CHECK(t == Approx(0.0).margin(1e-12));
        ++exact;
      } else {
        CHECK(t >= -1e-12);  // never below the exact value
      }
    }
  }
  CHECK(exact >= 64);
}

TEST_CASE("the Morton order visits the cells in Z pattern", "[voronoi][fmm]") {
  const CartesianGrid g = CartesianGrid::spanning({0, 0}, {4, 4}, 5, 5);
  // One point in each cell of the 4 x 4 cells, listed row by row.
  Eigen::Matrix2Xd p(2, 16);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) p.col(4 * j + i) = Eigen::Vector2d(i + 0.5, j + 0.5);
  // Z of Z's: the 2 x 2 quadrants in turn, each in the order (0,0) (1,0) (0,1) (1,1).
  const std::vector<int> expected{0, 1, 4, 5, 2, 3, 6, 7, 8, 9, 12, 13, 10, 11, 14, 15};
  CHECK(morton_order(g, p) == expected);
}

TEST_CASE("label contacts: pairs across grid edges, crystals at the outside", "[voronoi][fmm]") {
  // A 4 x 3 grid, labels by row (j = 0 at the bottom), the domain all but
  // the top-right node:
  //   2  2  1  .
  //   0  2  1  1
  //   0  0  1  1
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({0, 0}, {3, 2}, 4, 3);
  p.seeds = Eigen::Matrix2Xd::Zero(2, 3);
  p.domain = -Eigen::VectorXd::Ones(12);
  p.domain(11) = 1.0;
  Eigen::VectorXi labels(12);
  labels << 0, 0, 1, 1, 0, 2, 1, 1, 2, 2, 1, -1;
  const LabelContacts c = label_contacts(StencilField(p), labels, 3);
  CHECK(c.collisions == std::vector<std::array<int, 2>>{{0, 1}, {0, 2}, {1, 2}});
  CHECK(c.boundary_contacts == std::vector<int>{1});
  p.domain.resize(0);
  labels(11) = 1;
  CHECK(label_contacts(StencilField(p), labels, 3).boundary_contacts.empty());
}

TEST_CASE("fast marching labels match the exact metric Voronoi diagram at anisotropy 1, 10, 100",
          "[voronoi][fmm]") {
  // Each constant metric three ways: as it is (the update is the exact seed
  // distance); as a metric field whose corner tensors differ in the last
  // bits (every node has its own stencil and every update does the Hopf-Lax,
  // source and reverse-stencil work); and that with the unit square as a
  // domain (visibility and clearance tests on every update). The exact
  // answer is the same, and so must the labels be.
  const int n = 301;
  const Eigen::Matrix2Xd seeds = test::uniform_seeds(20, 3, 0.05, 0.95);
  const CartesianGrid coarse = CartesianGrid::spanning({0, 0}, {1, 1}, 5, 5);
  for (const double ratio : {1.0, 10.0, 100.0}) {
    INFO("anisotropy 1:" << ratio);
    const Eigen::Matrix2d M = metric_from_axes(0.5, 1.0, 1.0 / ratio);
    VoronoiProblem p = unit_square(n, seeds, M);
    check_labels(p, seeds, M);
    std::vector<Eigen::Matrix2d> corners;
    for (int k = 0; k < coarse.node_count(); ++k) corners.push_back(M * (1.0 + 1e-12 * k));
    p.metric = MetricField(coarse, corners);
    REQUIRE(!p.metric.uniform());
    check_labels(p, seeds, M);
    p.domain = sample_on_grid(p.grid, [](const Eigen::Vector2d& x) {
      return -std::min({x.x(), x.y(), 1.0 - x.x(), 1.0 - x.y()});
    });
    check_labels(p, seeds, M);
  }
}

TEST_CASE("fast marching labels stay exact with dense seeds (many blocks of crystals)",
          "[voronoi][fmm]") {
  // About 25 nodes per crystal, as 1.6e5 seeds on 2000 x 2000: the crystals
  // grow in many blocks and windows, and at nearly every node two crystals
  // meet within one window. Labels as exact as one heap of all crystals.
  const int n = 201;
  const Eigen::Matrix2Xd seeds = test::uniform_seeds(1600, 5, 0.0, 1.0);
  // Steps (entries accepted) per node at most: the own times one stencil
  // step past each interface, longer steps at 1:10 (one heap of all
  // crystals, before the blocks, took 2.5 and 12.7), not a window's worth of
  // growth past every interface.
  for (const auto& [ratio, steps] : {std::pair<double, int>{1.0, 3}, {10.0, 8}}) {
    INFO("anisotropy 1:" << ratio);
    const Eigen::Matrix2d M = metric_from_axes(0.5, 1.0, 1.0 / ratio);
    const VoronoiProblem p = unit_square(n, seeds, M);
    CHECK(check_labels(p, seeds, M).steps < steps * p.grid.node_count());
  }
}

TEST_CASE("fast marching duals are the exact metric Delaunay triangulations", "[voronoi][fmm]") {
  // Seeds in general position (no four within 2 cells of cocircular in the
  // metric, no Voronoi vertex within 8 cells of the border): the dual must be
  // the Delaunay triangulation of the seeds mapped by L^T, M = L L^T. At
  // 1:100 the regions in a square are strips crossing it, a few cells wide: a
  // finer grid, and the sets that have a Voronoi vertex in the square.
  for (const auto& [ratio, n] : {std::pair<double, int>{1.0, 301}, {10.0, 301}, {100.0, 1001}}) {
    INFO("anisotropy 1:" << ratio);
    const Eigen::Matrix2d M = metric_from_axes(-0.3, 1.0, 1.0 / ratio);
    const Eigen::Matrix2d Lt = M.llt().matrixL().transpose();
    int tested = 0;
    for (const Eigen::Matrix2Xd& seeds : test::general_seed_sets(4, 25, 1.0 / (n - 1), M)) {
      const auto expected = test::delaunay_in_box(seeds, 0.0, 1.0, Lt).triangles;
      if (expected.empty() || tested == 2) continue;
      ++tested;
      const VoronoiDelaunay v = voronoi_delaunay(unit_square(n, seeds, M), "fast_marching");
      CHECK(v.check.ok());
      CHECK(test::rotated(v.dual.triangles) == expected);
      // Orphans: slivers of a region thinner than a cell where it meets the
      // border, cut into pieces by the grid (the exact labels do the same).
      for (const int o : v.regions.orphans) CHECK(v.regions.regions[o].nodes <= 10);
    }
    CHECK(tested == 2);
  }
}

TEST_CASE("fast marching in a disc and an annulus: geodesic regions, valid duals",
          "[voronoi][fmm]") {
  const int n = 201;
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({-1, -1}, {1, 1}, n, n);
  const int K = 16;
  p.seeds.resize(2, 2 * K);
  for (int k = 0; k < K; ++k) {
    const double a = 2 * M_PI * k / K, b = 2 * M_PI * (k + 0.5) / K;
    p.seeds.col(k) = 0.45 * Eigen::Vector2d(std::cos(a), std::sin(a));
    p.seeds.col(K + k) = 0.75 * Eigen::Vector2d(std::cos(b), std::sin(b));
  }
  SECTION("annulus") {
    p.domain = sample_on_grid(
        p.grid, [](const Eigen::Vector2d& x) { return std::abs(x.norm() - 0.6) - 0.3; });
    const VoronoiDelaunay v = voronoi_delaunay(p, "fast_marching");
    CHECK(v.valid());
    CHECK(v.regions.domain_euler == 0);
    CHECK(v.dual.triangles.size() == 2 * K);
    // No node outside is labelled; every seed's region reaches the boundary.
    for (int k = 0; k < p.grid.node_count(); ++k)
      if (p.domain(k) > 0) REQUIRE(v.partition.labels(k) == -1);
    CHECK(v.partition.boundary_contacts.size() == 2 * K);
  }
  SECTION("a wall: crystals do not see through it") {
    // The disc of radius 0.9 cut by a wall 4 cells thick along x = 0 from the
    // bottom up to y = 0.5: seeds either side of the wall meet only above it.
    p.seeds.resize(2, 2);
    p.seeds << -0.2, 0.2,  //
        -0.5, -0.5;
    p.domain = sample_on_grid(p.grid, [](const Eigen::Vector2d& x) {
      const double wall = std::max(std::abs(x.x()) - 0.02, x.y() - 0.5);  // < 0 in it
      return std::max(x.norm() - 0.9, -wall);
    });
    const CrystalPartition r = grow_crystals(p, "fast_marching");
    // Below the wall's top, the side decides the label: the geodesic round
    // the wall is longer than the straight path through it.
    int crossed = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Eigen::Vector2d x = p.grid.point(i, j);
        const int l = r.labels(p.grid.index(i, j));
        if (l >= 0 && x.y() < 0.3) crossed += (x.x() < 0) != (l == 0);
      }
    CHECK(crossed == 0);
    CHECK(r.collisions == std::vector<std::array<int, 2>>{{0, 1}});
  }
}

TEST_CASE("fast marching on shared stencils: the same labels, and none for another problem",
          "[voronoi][fmm]") {
  // A graded metric in an annulus (stencils per node), grown once with its own
  // stencils and again with them shared, with the seeds moved as Lloyd moves them.
  const int n = 121;
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({-1, -1}, {1, 1}, n, n);
  p.domain = sample_on_grid(
      p.grid, [](const Eigen::Vector2d& x) { return std::abs(x.norm() - 0.6) - 0.3; });
  const CartesianGrid coarse = CartesianGrid::spanning({-1, -1}, {1, 1}, 5, 5);
  std::vector<Eigen::Matrix2d> M(25);
  for (int k = 0; k < 25; ++k) M[k] = Eigen::Vector2d(1.0 + k, 4.0 + 0.5 * k).asDiagonal();
  p.metric = MetricField(coarse, M);
  p.seeds.resize(2, 12);
  for (int k = 0; k < 12; ++k)
    p.seeds.col(k) = (k % 2 ? 0.45 : 0.75) *
                     Eigen::Vector2d(std::cos(2 * M_PI * k / 12), std::sin(2 * M_PI * k / 12));
  const CrystalPartition own = grow_crystals(p, "fast_marching");
  VoronoiProblem shared = p;
  share_stencils(shared, "fast_marching");
  REQUIRE(shared.stencils);
  CHECK(shared.stencils->built_for(p));
  const std::shared_ptr<const StencilField> built = shared.stencils;
  share_stencils(shared, "fast_marching");  // built for it already: kept
  CHECK(shared.stencils == built);
  CHECK(grow_crystals(shared, "fast_marching").labels == own.labels);
  shared.seeds.col(3) += Eigen::Vector2d(0.03, -0.02);
  p.seeds = shared.seeds;
  CHECK(grow_crystals(shared, "fast_marching").labels == grow_crystals(p, "fast_marching").labels);
  // Another domain, metric or grid: the stencils are not those of the problem.
  VoronoiProblem other = shared;
  other.domain(other.domain.size() / 2) += 0.1;
  CHECK_FALSE(built->built_for(other));
  other = shared;
  other.metric = MetricField::constant(Eigen::Matrix2d::Identity());
  CHECK_FALSE(built->built_for(other));
  other = shared;
  other.grid.dx *= 1.0 + 1e-12;
  CHECK_FALSE(built->built_for(other));
  // The level-set engine has no stencils to share.
  VoronoiProblem level_set = p;
  share_stencils(level_set, "level_set");
  CHECK_FALSE(level_set.stencils);
}

TEST_CASE("fast marching refuses what it cannot do", "[voronoi][fmm]") {
  VoronoiProblem p =
      unit_square(21, test::uniform_seeds(3, 1, 0.1, 0.9), Eigen::Matrix2d::Identity());
  p.contact = Contact::wet;
  CHECK_THROWS_WITH(grow_crystals(p, "fast_marching"), Catch::Contains("dry"));
  p.contact = Contact::dry;
  p.seeds(0, 1) = 1.5;
  CHECK_THROWS_WITH(grow_crystals(p, "fast_marching"),
                    Catch::Contains("seed 1 lies outside the grid"));
  p.seeds(0, 1) = 0.5;
  p.domain = sample_on_grid(p.grid, [](const Eigen::Vector2d& x) { return x.x() - 0.3; });
  CHECK_THROWS_WITH(grow_crystals(p, "fast_marching"), Catch::Contains("lies outside the domain"));
  CHECK_THROWS_WITH(voronoi_engine("fast"), Catch::Contains("fast_marching"));
}
