#include "voronoi/dual/conforming_dual.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <set>

#include "../voronoi_test_support.h"
#include "core/error.h"
#include "voronoi/dual/cgal_delaunay.h"
#include "voronoi/grid/orient2d.h"

using namespace homesh;

namespace {

// A polygon with corners on the unit lattice, `per_unit` boundary seeds per
// unit length counter-clockwise, and jittered lattice seeds inside.
struct Polygon {
  Eigen::Matrix2Xd seeds;
  std::vector<std::array<int, 2>> boundary;
  double area = 0.0;
};

Polygon polygon(const std::vector<Eigen::Vector2d>& corners, int per_unit) {
  std::vector<Eigen::Vector2d> pts;
  Polygon p;
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const Eigen::Vector2d a = corners[c], b = corners[(c + 1) % corners.size()];
    p.area += 0.5 * (a.x() * b.y() - a.y() * b.x());
    const int n = static_cast<int>(std::lround((b - a).norm() * per_unit));
    for (int k = 0; k < n; ++k) pts.push_back(a + (b - a) * (static_cast<double>(k) / n));
  }
  const int B = static_cast<int>(pts.size());
  for (int k = 0; k < B; ++k) p.boundary.push_back({k, (k + 1) % B});
  const double h = 1.0 / per_unit;
  const Eigen::Matrix2Xd jitter = test::uniform_seeds(1000, 5, -0.25, 0.25);
  int m = 0;
  for (double y = h; y < 2 - 0.5 * h; y += h)
    for (double x = h; x < 2 - 0.5 * h; x += h) {
      const Eigen::Vector2d q = Eigen::Vector2d(x, y) + h * jitter.col(m++ % 1000);
      bool inside = false;  // even-odd over the corners, and clear of the edges
      double clearance = 1e300;
      for (std::size_t c = 0; c < corners.size(); ++c) {
        const Eigen::Vector2d a = corners[c], b = corners[(c + 1) % corners.size()];
        if ((a.y() > q.y()) != (b.y() > q.y()) &&
            q.x() < a.x() + (q.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
          inside = !inside;
        const double t = std::clamp((q - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
        clearance = std::min(clearance, (q - a - t * (b - a)).norm());
      }
      if (inside && clearance > 0.5 * h) pts.push_back(q);
    }
  p.seeds.resize(2, static_cast<Eigen::Index>(pts.size()));
  for (std::size_t k = 0; k < pts.size(); ++k) p.seeds.col(k) = pts[k];
  return p;
}

const std::vector<Eigen::Vector2d> kSquare{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
const std::vector<Eigen::Vector2d> kL{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};

// The triangles tile the polygon with every boundary segment an edge: all
// counter-clockwise, interior edges twice in opposite directions, boundary
// segments once in their own direction, and the areas add up.
void check_tiles(const Polygon& p, const std::vector<std::array<int, 3>>& triangles) {
  std::map<std::array<int, 2>, int> directed;
  double area = 0.0;
  for (const auto& t : triangles) {
    const Eigen::Vector2d a = p.seeds.col(t[0]), b = p.seeds.col(t[1]), c = p.seeds.col(t[2]);
    REQUIRE(orient2d(a, b, c) > 0);
    area += 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  CHECK(area == Approx(p.area).epsilon(1e-12));
  const std::set<std::array<int, 2>> walls(p.boundary.begin(), p.boundary.end());
  for (const auto& [a, b] : p.boundary) {
    CHECK(directed.count({a, b}) == 1);
    CHECK(directed.count({b, a}) == 0);
  }
  for (const auto& [e, n] : directed) {
    CHECK(n == 1);
    if (!walls.count(e)) CHECK(directed.count({e[1], e[0]}) == 1);
  }
}

}  // namespace

TEST_CASE("a dual that conforms is kept whole", "[voronoi][conforming]") {
  const Polygon p = polygon(kSquare, 6);
  const auto dual = cgal_delaunay_triangles(p.seeds);
  const ConformingTriangulation r = conforming_triangulation(p.seeds, p.boundary, dual);
  check_tiles(p, r.triangles);
  CHECK(r.triangles == dual);
  CHECK(r.from_dual == static_cast<int>(dual.size()));
  CHECK(r.filled == 0);
  CHECK(r.dual_dropped == 0);
  CHECK(r.boundary_missed == 0);
}

TEST_CASE("dual triangles outside a concave boundary are dropped", "[voronoi][conforming]") {
  const Polygon p = polygon(kL, 6);
  // CGAL's Delaunay covers the convex hull, the notch of the L included.
  const auto dual = cgal_delaunay_triangles(p.seeds);
  const ConformingTriangulation r = conforming_triangulation(p.seeds, p.boundary, dual);
  check_tiles(p, r.triangles);
  CHECK(r.dual_dropped > 0);
  CHECK(r.from_dual + r.dual_dropped == static_cast<int>(dual.size()));
  CHECK(r.from_dual + r.filled == static_cast<int>(r.triangles.size()));
}

TEST_CASE("a damaged dual is filled by the constrained Delaunay triangulation",
          "[voronoi][conforming]") {
  const Polygon p = polygon(kL, 6);
  std::vector<std::array<int, 3>> dual = cgal_delaunay_triangles(p.seeds);
  // Every third triangle lost, one turned clockwise, one overlapping.
  std::vector<std::array<int, 3>> damaged;
  for (std::size_t f = 0; f < dual.size(); ++f)
    if (f % 3 != 0) damaged.push_back(dual[f]);
  std::swap(damaged[1][1], damaged[1][2]);
  damaged.push_back({damaged[5][0], damaged[5][1], damaged[8][2]});
  const ConformingTriangulation r = conforming_triangulation(p.seeds, p.boundary, damaged);
  check_tiles(p, r.triangles);
  CHECK(r.filled > static_cast<int>(dual.size()) / 4);
  CHECK(r.boundary_missed > 0);
  // No edge shared by two triangles on the same side: the overlap was dropped.
  CHECK(r.from_dual < static_cast<int>(damaged.size()));
}

TEST_CASE("a self-crossing boundary is refused", "[voronoi][conforming]") {
  Eigen::Matrix2Xd seeds(2, 4);
  seeds << 0, 1, 1, 0,  //
      0, 1, 0, 1;
  CHECK_THROWS_AS(conforming_triangulation(seeds, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, {}), Error);
}
