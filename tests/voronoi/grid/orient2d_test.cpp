#include "voronoi/grid/orient2d.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "voronoi/dual/cgal_delaunay.h"

using namespace homesh;

TEST_CASE("orient2d gives the sign of the determinant on exactly representable cases",
          "[voronoi][orient2d]") {
  CHECK(orient2d({0, 0}, {1, 0}, {0, 1}) == 1);
  CHECK(orient2d({0, 0}, {0, 1}, {1, 0}) == -1);
  CHECK(orient2d({0, 0}, {1, 1}, {3, 3}) == 0);
  CHECK(orient2d({1e-100, 0}, {0, 1e-100}, {0, 0}) == 1);
  CHECK(orient2d({1e100, 0}, {0, 1e100}, {0, 0}) == 1);
  // Cyclic invariance and sign change under a swap.
  const Eigen::Vector2d a(0.3, 0.7), b(-1.2, 0.1), c(2.5, -0.4);
  CHECK(orient2d(a, b, c) == orient2d(b, c, a));
  CHECK(orient2d(a, b, c) == -orient2d(b, a, c));
}

TEST_CASE("orient2d agrees with CGAL's exact orientation where doubles fail",
          "[voronoi][orient2d]") {
  // Shewchuk's example: a = (0.5 + i u, 0.5 + j u) for a 64 x 64 patch of
  // u = 2^-53, against b = (12, 12), c = (24, 24). Naive evaluation gets many
  // signs wrong; the exact predicate must match CGAL's everywhere.
  const double u = std::ldexp(1.0, -53);
  const Eigen::Vector2d b(12, 12), c(24, 24);
  int naive_wrong = 0, mismatches = 0, nonzero = 0;
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      const Eigen::Vector2d a(0.5 + i * u, 0.5 + j * u);
      const int exact = cgal_orientation(a, b, c);
      mismatches += orient2d(a, b, c) != exact;
      nonzero += exact != 0;
      const double naive = (a.x() - c.x()) * (b.y() - c.y()) - (a.y() - c.y()) * (b.x() - c.x());
      naive_wrong += ((naive > 0) - (naive < 0)) != exact;
    }
  }
  CHECK(mismatches == 0);
  CHECK(nonzero > 1000);
  CHECK(naive_wrong > 100);
}
