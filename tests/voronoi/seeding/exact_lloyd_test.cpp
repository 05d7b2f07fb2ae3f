#include "voronoi/seeding/exact_lloyd.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "voronoi/dual/cgal_delaunay.h"

using namespace homesh;

namespace {

// Signed distance of the square [-4, 4]^2 (< 0 inside).
double square(const Eigen::Vector2d& x) { return x.cwiseAbs().maxCoeff() - 4.0; }

// Fixed seeds on the integer points of [-4, 4]^2 but those listed free.
Eigen::Matrix2Xd lattice_with(const Eigen::Matrix2Xd& free) {
  Eigen::Matrix2Xd s(2, 81 - 1 + free.cols());
  int k = 0;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j)
      if (i != 0 || j != 0) s.col(k++) = Eigen::Vector2d(i, j);
  s.rightCols(free.cols()) = free;
  return s;
}

// The centroid of the points of [-2, 2]^2 nearest to seed `s` (brute force
// on an n x n sampling), weighted by sqrt(det M) M of an isotropic or
// constant metric (its (0, 0) entry then weighs).
Eigen::Vector2d brute_centroid(const Eigen::Matrix2Xd& seeds, Eigen::Index s, int n,
                               const MetricField& metric) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double count = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const Eigen::Vector2d x(-2.0 + 4.0 * (a + 0.5) / n, -2.0 + 4.0 * (b + 0.5) / n);
      Eigen::Index best = 0;
      (seeds.colwise() - x).colwise().squaredNorm().minCoeff(&best);
      if (best == s) {
        const Eigen::Matrix2d M = metric.metric_at(x);
        const double w = metric.uniform() ? 1.0 : std::sqrt(M.determinant()) * M(0, 0);
        sum += w * x;
        count += w;
      }
    }
  return sum / count;
}

// One exact Lloyd step of the last seed, the others fixed.
Eigen::Matrix2Xd one_step(const Eigen::Matrix2Xd& seeds, const MetricField& metric,
                          const std::function<double(const Eigen::Vector2d&)>& domain) {
  LloydOptions one;
  one.iterations = 1;
  return exact_lloyd(seeds, static_cast<int>(seeds.cols() - 1), metric, domain, one);
}

}  // namespace

TEST_CASE("voronoi cells: a lattice point's cell is its unit square, a hull point's is unbounded",
          "[voronoi][lloyd]") {
  const Eigen::Matrix2Xd seeds = lattice_with(Eigen::Vector2d(0.0, 0.0));
  const VoronoiCells c = cgal_voronoi_cells(seeds);
  const std::vector<Eigen::Vector2d>& cell = c.vertices.back();
  double area = 0;
  for (std::size_t k = 0; k < cell.size(); ++k) {
    const Eigen::Vector2d& u = cell[k];
    const Eigen::Vector2d& v = cell[(k + 1) % cell.size()];
    area += 0.5 * (u.x() * v.y() - u.y() * v.x());
    CHECK(u.cwiseAbs().maxCoeff() == Approx(0.5));
  }
  CHECK(area == Approx(1.0));  // counter-clockwise
  CHECK(c.neighbours.back().size() >= 4);
  CHECK(c.vertices[0].empty());  // (-4, -4): a corner of the hull
}

TEST_CASE("exact Lloyd: one step is the brute-force centroid of the nearest-seed region",
          "[voronoi][lloyd]") {
  const Eigen::Matrix2Xd seeds = lattice_with(Eigen::Vector2d(0.3, 0.2));
  const Eigen::Index s = seeds.cols() - 1;
  const MetricField constant = MetricField::constant(metric_from_axes(0.4, 2.0, 0.5));
  const Eigen::Matrix2Xd moved = one_step(seeds, constant, square);
  const Eigen::Vector2d expected = brute_centroid(seeds, s, 800, constant);
  CHECK((moved.col(s) - expected).norm() < 2e-3);
  CHECK((moved.col(s) - seeds.col(s)).norm() > 0.1);  // it did move
  CHECK(moved.leftCols(s) == seeds.leftCols(s));      // the fixed seeds did not
}

TEST_CASE("exact Lloyd: a cell the boundary cuts is integrated over its inside",
          "[voronoi][lloyd]") {
  // The lattice point's unit cell cut by the wall x = 0.25: its inside is
  // [-0.5, 0.25] x [-0.5, 0.5], centroid (-0.125, 0), to the sub-triangles'
  // sampling (1/36 of each fan triangle).
  const Eigen::Matrix2Xd seeds = lattice_with(Eigen::Vector2d(0.0, 0.0));
  const Eigen::Index s = seeds.cols() - 1;
  const auto cut = [](const Eigen::Vector2d& x) { return std::max(square(x), x.x() - 0.25); };
  const MetricField unit = MetricField::constant(Eigen::Matrix2d::Identity());
  const Eigen::Matrix2Xd moved = one_step(seeds, unit, cut);
  CHECK(moved(0, s) == Approx(-0.125).margin(0.01));
  CHECK(moved(1, s) == Approx(0.0).margin(1e-9));
  // Uncut, the cell's centroid is the seed itself.
  CHECK(one_step(seeds, unit, square).col(s).norm() < 1e-12);
}

TEST_CASE("exact Lloyd: the centre of a symmetric ring is its fixed point; a density pulls",
          "[voronoi][lloyd]") {
  LloydOptions many;
  many.iterations = 40;
  const Eigen::Matrix2Xd seeds = lattice_with(Eigen::Vector2d(0.35, -0.25));
  const Eigen::Index s = seeds.cols() - 1;
  const MetricField unit = MetricField::constant(Eigen::Matrix2d::Identity());
  const Eigen::Matrix2Xd relaxed = exact_lloyd(seeds, static_cast<int>(s), unit, square, many);
  CHECK(relaxed.col(s).norm() < 5e-3);  // stops once no seed moves by 1e-3
  // Sizes h(x) = 2^(x / 2) (isotropic, M = I / h^2): one step takes the
  // centroid weighted by h^-4 (brute force, to the midpoint rule's error),
  // and the iteration settles on the finer side, on the axis of symmetry.
  const CartesianGrid coarse = CartesianGrid::spanning({-5, -5}, {5, 5}, 201, 201);
  std::vector<Eigen::Matrix2d> M(coarse.node_count());
  for (int j = 0; j < coarse.ny; ++j)
    for (int i = 0; i < coarse.nx; ++i) {
      const double h = std::pow(2.0, 0.5 * coarse.point(i, j).x());
      M[coarse.index(i, j)] = Eigen::Matrix2d::Identity() / (h * h);
    }
  const MetricField graded(coarse, M);
  CHECK(graded.anisotropy() == Approx(1.0));
  const Eigen::Matrix2Xd step = one_step(seeds, graded, square);
  CHECK((step.col(s) - brute_centroid(seeds, s, 800, graded)).norm() < 5e-3);
  CHECK((step.col(s) - brute_centroid(seeds, s, 800, unit)).norm() > 0.05);  // the weight tells
  const Eigen::Matrix2Xd pulled = exact_lloyd(seeds, static_cast<int>(s), graded, square, many);
  CHECK(pulled(0, s) < -0.2);
  CHECK(std::abs(pulled(1, s)) < 5e-3);
}

TEST_CASE("exact Lloyd: lowers the CVT energy of random seeds and keeps them in the domain",
          "[voronoi][lloyd]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-3.6, 3.6);
  // Fixed: a ring of 64 seeds on the square's boundary; free: 60 random ones.
  Eigen::Matrix2Xd seeds(2, 64 + 60);
  for (int k = 0; k < 16; ++k) {
    const double t = -4.0 + 0.5 * k;
    seeds.col(4 * k) = Eigen::Vector2d(t, -4);
    seeds.col(4 * k + 1) = Eigen::Vector2d(4, t);
    seeds.col(4 * k + 2) = Eigen::Vector2d(-t, 4);
    seeds.col(4 * k + 3) = Eigen::Vector2d(-4, -t);
  }
  for (int k = 64; k < seeds.cols(); ++k) seeds.col(k) = Eigen::Vector2d(u(rng), u(rng));
  const auto energy = [](const Eigen::Matrix2Xd& s) {
    double e = 0;
    const int n = 200;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        const Eigen::Vector2d x(-4.0 + 8.0 * (a + 0.5) / n, -4.0 + 8.0 * (b + 0.5) / n);
        e += (s.colwise() - x).colwise().squaredNorm().minCoeff();
      }
    return e;
  };
  LloydOptions o;
  o.iterations = 20;
  const Eigen::Matrix2Xd relaxed =
      exact_lloyd(seeds, 64, MetricField::constant(Eigen::Matrix2d::Identity()), square, o);
  CHECK(energy(relaxed) < 0.8 * energy(seeds));
  for (Eigen::Index k = 64; k < relaxed.cols(); ++k) CHECK(square(relaxed.col(k)) < 0.0);
  CHECK(MetricField::constant(metric_from_axes(0.3, 4.0, 1.0)).anisotropy() == Approx(4.0));
}
