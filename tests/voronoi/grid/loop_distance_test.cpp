#include "voronoi/grid/loop_distance.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace homesh;

namespace {

Eigen::Matrix2Xd circle(double r, int n, bool clockwise) {
  Eigen::Matrix2Xd p(2, n);
  for (int k = 0; k < n; ++k) {
    const double a = (clockwise ? -2 : 2) * M_PI * k / n;
    p.col(k) << r * std::cos(a), r * std::sin(a);
  }
  return p;
}

}  // namespace

TEST_CASE("signed distance of an annulus from its two sampled circles", "[voronoi][domain]") {
  // Radii 0.3 and 0.8, sampled finely: the exact signed distance is
  // max(|x| - 0.8, 0.3 - |x|) within the band, +-band beyond.
  const CartesianGrid g = CartesianGrid::spanning({-1, -1}, {1, 1}, 101, 101);
  const std::vector<Eigen::Matrix2Xd> loops{circle(0.8, 2000, false), circle(0.3, 800, true)};
  const double band = 0.1;
  const Eigen::VectorXd d = loop_signed_distance(g, loops, band);
  double worst = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double r = g.point(i, j).norm();
      const double exact = std::max(r - 0.8, 0.3 - r);
      const double got = d(g.index(i, j));
      if (std::abs(exact) < band - 1e-3)
        worst = std::max(worst, std::abs(got - exact));
      else if (std::abs(exact) > band + 1e-3)
        CHECK(got == (exact > 0 ? band : -band));
      if (std::abs(exact) > 1e-3) CHECK(inside_loops(loops, g.point(i, j)) == (exact < 0));
    }
  // Chords of 2000 and 800 sides sag by r (1 - cos(pi / n)) < 2e-6; the
  // decimated chords pass within 0.01 cells (2e-4) of the samples they skip.
  CHECK(worst < 0.01 * g.ds() + 1e-5);
}
