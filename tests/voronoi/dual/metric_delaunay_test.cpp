#include "voronoi/dual/metric_delaunay.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <catch2/catch.hpp>
#include <random>

#include "voronoi/dual/cgal_constrained_delaunay.h"
#include "voronoi/dual/cgal_delaunay.h"

using namespace homesh;

namespace {

// Each triangle rotated to start at its smallest index, then sorted.
std::vector<std::array<int, 3>> canonical(std::vector<std::array<int, 3>> t) {
  for (auto& a : t) std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
  std::sort(t.begin(), t.end());
  return t;
}

}  // namespace

TEST_CASE("in_metric_circle: the circle through three points, in the metric", "[voronoi][dual]") {
  const Eigen::Vector2d a(0, 0), b(1, 0), c(0, 1);
  // Euclidean: (0.9, 0.9) lies inside the circle of centre (0.5, 0.5), radius 0.707.
  CHECK(in_metric_circle(a, b, c, {0.9, 0.9}, Eigen::Matrix2d::Identity()));
  CHECK_FALSE(in_metric_circle(a, b, c, {1.1, 1.1}, Eigen::Matrix2d::Identity()));
  // With M = diag(1, 100) the points map to (0, 0), (1, 0), (0, 10), whose
  // circle has centre (0.5, 5) and radius^2 25.25: (1.3, 0.5) maps to
  // (1.3, 5), inside, though outside the Euclidean circle; (2, 1) to (2, 10),
  // outside both.
  const Eigen::Matrix2d M = Eigen::Vector2d(1, 100).asDiagonal();
  CHECK_FALSE(in_metric_circle(a, b, c, {1.3, 0.5}, Eigen::Matrix2d::Identity()));
  CHECK(in_metric_circle(a, b, c, {1.3, 0.5}, M));
  CHECK(in_metric_circle(a, b, c, {0.9, 0.9}, M));
  CHECK_FALSE(in_metric_circle(a, b, c, {2, 1}, M));
}

TEST_CASE(
    "metric_delaunay_flips: in a constant anisotropic metric, the Delaunay triangulation of "
    "the mapped seeds",
    "[voronoi][dual]") {
  // Random seeds in the unit square (its corners and edges as the boundary),
  // metric 30:1 turned by 30 degrees.
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(0.02, 0.98);
  const int n = 300;
  Eigen::Matrix2Xd x(2, n + 4);
  x.col(0) << 0, 0;
  x.col(1) << 1, 0;
  x.col(2) << 1, 1;
  x.col(3) << 0, 1;
  for (int k = 4; k < n + 4; ++k) x.col(k) << u(gen), u(gen);
  const double t = M_PI / 6;
  Eigen::Matrix2d R;
  R << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
  const Eigen::Matrix2d M = R * Eigen::Vector2d(1, 900).asDiagonal() * R.transpose();
  const MetricField metric = MetricField::constant(M);
  const std::vector<std::array<int, 2>> square = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  std::vector<std::array<int, 3>> tri = cgal_constrained_triangles(x, square, {});
  // With no sweep, the triangles left with an edge not Delaunay in M, as
  // counted edge by edge here.
  std::vector<std::array<int, 3>> unswept = tri;
  const MetricDelaunay none = metric_delaunay_flips(x, unswept, square, metric, 0);
  CHECK(none.flips == 0);
  CHECK(unswept == tri);
  std::vector<char> bad(tri.size(), 0);
  for (std::size_t e = 0; e < tri.size(); ++e)
    for (std::size_t f = 0; f < tri.size(); ++f)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const int a = tri[e][i], b = tri[e][(i + 1) % 3];
          if (tri[f][j] != b || tri[f][(j + 1) % 3] != a) continue;
          const int c = tri[e][(i + 2) % 3], dd = tri[f][(j + 2) % 3];
          if (in_metric_circle(
                  x.col(a), x.col(b), x.col(c), x.col(dd),
                  metric.metric_at(0.25 * (x.col(a) + x.col(b) + x.col(c) + x.col(dd)))))
            bad[e] = bad[f] = 1;
        }
  const long brute = std::count(bad.begin(), bad.end(), 1);
  CHECK(brute > 100);
  CHECK(none.not_delaunay == brute);
  const MetricDelaunay d = metric_delaunay_flips(x, tri, square, metric);
  CHECK(d.flips > 100);
  CHECK(d.not_delaunay == 0);
  // Every interior edge locally Delaunay in M: the mapped points' Delaunay
  // triangulation, but where the square's edges (constraints, not convex
  // in the mapped plane's hull sense) cut it.
  const Eigen::Matrix2d L = M.llt().matrixU();
  const Eigen::Matrix2Xd mapped = L * x;
  const std::vector<std::array<int, 3>> want = canonical(cgal_delaunay_triangles(mapped));
  const std::vector<std::array<int, 3>> got = canonical(tri);
  int shared = 0;
  for (const auto& g : got) shared += std::binary_search(want.begin(), want.end(), g);
  // The mapped square is a parallelogram, so its hull is the same: all of
  // them, up to cocircular ties.
  CHECK(got.size() == want.size());
  CHECK(shared >= static_cast<int>(got.size()) - 2);
}
