#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "core/error.h"
#include "voronoi/engines/voronoi_engines.h"

using namespace homesh;

namespace {

// One crystal from the origin on [-1, 1]^2, stopped at time t.
CrystalPartition grow_one(const Eigen::Matrix2d& M, double t, int n) {
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({-1, -1}, {1, 1}, n, n);
  p.seeds = Eigen::Matrix2Xd::Zero(2, 1);
  p.metric = MetricField::constant(M);
  VoronoiOptions o;
  o.stop_time = t;
  return grow_crystals(p, "level_set", o);
}

// Support function of the crystal's nodes: max over nodes of N . x.
double support(const CartesianGrid& g, const Eigen::VectorXi& labels, const Eigen::Vector2d& N) {
  double h = -1e300;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      if (labels(g.index(i, j)) == 0) h = std::max(h, N.dot(g.point(i, j)));
  return h;
}

}  // namespace

TEST_CASE("an isolated crystal in a constant isotropic metric grows as a circle of radius h t",
          "[voronoi][level_set]") {
  const int n = 201;
  const double h = 0.5, ds = 0.01;
  for (const double t : {0.8, 1.2, 1.6}) {
    INFO("t = " << t);
    const CrystalPartition r = grow_one(metric_from_axes(0.0, h, h), t, n);
    const CartesianGrid g = CartesianGrid::spanning({-1, -1}, {1, 1}, n, n);
    CHECK(r.time == Approx(t));
    CHECK_FALSE(r.settled);
    const double area = (r.labels.array() == 0).count() * ds * ds;
    CHECK(std::abs(std::sqrt(area / M_PI) - h * t) < 0.5 * ds);
    double worst = 0.0;
    for (int k = 0; k < 72; ++k) {
      const Eigen::Vector2d N(std::cos(k * M_PI / 36), std::sin(k * M_PI / 36));
      worst = std::max(worst, std::abs(support(g, r.labels, N) - h * t));
    }
    CHECK(worst < 1.5 * ds);
  }
}

TEST_CASE("an isolated crystal in a constant anisotropic metric grows as the metric's ellipse",
          "[voronoi][level_set]") {
  // The crystal at time t is {x : x^T M x <= t^2}: semi-axes t h1 along the
  // angle theta and t h2 across, i.e. the front moves along N at
  // sqrt(N^T M^-1 N). Eq 2.8 read literally, sqrt(N^T M N), would turn it by
  // 90 degrees.
  const int n = 201;
  const double theta = 0.5, h1 = 0.6, h2 = 0.2, t = 1.0, ds = 0.01;
  const Eigen::Matrix2d M = metric_from_axes(theta, h1, h2);
  const CrystalPartition r = grow_one(M, t, n);
  const CartesianGrid g = CartesianGrid::spanning({-1, -1}, {1, 1}, n, n);

  // Second moments: a filled ellipse of semi-axes a, b has covariance
  // eigenvalues a^2 / 4, b^2 / 4.
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  int count = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (r.labels(g.index(i, j)) == 0) {
        const Eigen::Vector2d x = g.point(i, j);
        mean += x;
        second += x * x.transpose();
        ++count;
      }
  mean /= count;
  const Eigen::Matrix2d cov = second / count - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
  const double a = 2 * std::sqrt(eig.eigenvalues()(1)), b = 2 * std::sqrt(eig.eigenvalues()(0));
  const Eigen::Vector2d major = eig.eigenvectors().col(1);
  const double angle =
      std::acos(std::abs(major.dot(Eigen::Vector2d(std::cos(theta), std::sin(theta)))));
  CHECK(mean.norm() < 0.5 * ds);
  CHECK(angle < 0.5 * M_PI / 180);
  CHECK(std::abs(a - h1 * t) < 2.0 * ds);
  CHECK(std::abs(b - h2 * t) < 1.0 * ds);
  CHECK(a / b == Approx(h1 / h2).epsilon(0.05));

  // The support function h(N) = t sqrt(N^T M^-1 N), to a few cells.
  const Eigen::Matrix2d Minv = M.inverse();
  double worst = 0.0;
  for (int k = 0; k < 72; ++k) {
    const Eigen::Vector2d N(std::cos(k * M_PI / 36), std::sin(k * M_PI / 36));
    worst = std::max(worst, std::abs(support(g, r.labels, N) - t * metric_speed(Minv, N)));
  }
  CHECK(worst < 2.0 * ds);
}

TEST_CASE("two crystals meet on the bisector of their seeds in the metric",
          "[voronoi][level_set]") {
  const int n = 201;
  const double ds = 1.0 / (n - 1);
  for (const bool anisotropic : {false, true}) {
    INFO("anisotropic = " << anisotropic);
    VoronoiProblem p;
    p.grid = CartesianGrid::spanning({0, 0}, {1, 1}, n, n);
    p.seeds.resize(2, 2);
    p.seeds << 0.3, 0.7, 0.35, 0.6;
    const Eigen::Matrix2d M =
        anisotropic ? metric_from_axes(-0.4, 0.3, 0.15) : Eigen::Matrix2d::Identity();
    p.metric = MetricField::constant(M);
    const CrystalPartition r = grow_crystals(p);
    CHECK(r.settled);
    CHECK((r.labels.array() >= 0).all());
    REQUIRE(r.collisions.size() == 1);
    CHECK(r.collisions[0] == std::array<int, 2>{0, 1});

    // The bisector {x : |x - a|_M = |x - b|_M} is the line n . x = c with
    // n = M (b - a), c = (|b|_M^2 - |a|_M^2) / 2. Interface: midpoints of grid
    // edges whose ends carry different labels; distance in cells.
    const Eigen::Vector2d a = p.seeds.col(0), b = p.seeds.col(1);
    const Eigen::Vector2d normal = M * (b - a);
    const double c = (b.dot(M * b) - a.dot(M * a)) / 2;
    double worst = 0.0;
    int edges = 0;
    const CartesianGrid& g = p.grid;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& [u, v] : {std::array<int, 2>{i + 1, j}, std::array<int, 2>{i, j + 1}}) {
          if (u >= n || v >= n || r.labels(g.index(i, j)) == r.labels(g.index(u, v))) continue;
          const Eigen::Vector2d mid = (g.point(i, j) + g.point(u, v)) / 2;
          worst = std::max(worst, std::abs(normal.dot(mid) - c) / normal.norm() / ds);
          ++edges;
        }
    CHECK(edges > n);
    CHECK(worst < 1.5);
  }
}

TEST_CASE("crystals with their own metrics meet on the Apollonius circle", "[voronoi][level_set]") {
  // Seed a grows in |x|/h_a, seed b in |x|/h_b (VoronoiProblem::seed_metrics,
  // as in Fig 2.4): the interface |x - a| / |x - b| = h_a / h_b = k is the
  // circle of centre (k^2 b - a) / (k^2 - 1) and radius k |b - a| / (k^2 - 1)
  // where a reaches it straight, on the arc facing a; behind b, crystal a
  // must grow round b's crystal and arrives later (the crystal-growth diagram
  // is not the multiplicatively weighted one there). The seed crystals differ
  // in metric radius, so they are born at different times.
  const int n = 201;
  const double ds = 1.0 / (n - 1), ha = 0.2, hb = 0.1, k = ha / hb;
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({0, 0}, {1, 1}, n, n);
  p.seeds.resize(2, 2);
  p.seeds << 0.3, 0.7, 0.5, 0.5;
  p.seed_metrics = {metric_from_axes(0.0, ha, ha), metric_from_axes(0.0, hb, hb)};
  const CrystalPartition r = grow_crystals(p);
  CHECK(r.settled);
  const Eigen::Vector2d a = p.seeds.col(0), b = p.seeds.col(1);
  const Eigen::Vector2d centre = (k * k * b - a) / (k * k - 1);
  const double radius = k * (b - a).norm() / (k * k - 1);
  double worst = 0.0;
  int edges = 0;
  const CartesianGrid& g = p.grid;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      if (r.labels(g.index(i, j)) == r.labels(g.index(i + 1, j))) continue;
      const Eigen::Vector2d mid = (g.point(i, j) + g.point(i + 1, j)) / 2;
      if ((mid - a).dot(mid - centre) >= 0.0) continue;
      worst = std::max(worst, std::abs((mid - centre).norm() - radius) / ds);
      ++edges;
    }
  CHECK(edges > 40);
  CHECK(worst < 1.5);
}

TEST_CASE("engines are chosen by name", "[voronoi][level_set]") {
  CHECK(voronoi_engine("level_set").name == "level_set");
  CHECK_FALSE(voronoi_engines().empty());
  try {
    voronoi_engine("nonsense");
    FAIL("no exception");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).find("level_set") != std::string::npos);
  }
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({0, 0}, {1, 1}, 11, 11);
  p.seeds = Eigen::Matrix2Xd::Constant(2, 1, 2.0);
  CHECK_THROWS_AS(grow_crystals(p), Error);
  p.seeds = Eigen::Matrix2Xd::Constant(2, 1, 0.5);
  p.seed_metrics = {Eigen::Matrix2d::Identity(), Eigen::Matrix2d::Identity()};
  CHECK_THROWS_AS(grow_crystals(p), Error);
}
