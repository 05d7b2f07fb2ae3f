#include "voronoi/seeding/point_buckets.h"

#include <catch2/catch.hpp>
#include <random>
#include <set>

using namespace homesh;

TEST_CASE("point buckets: a search finds every point within r, scanning about r around it",
          "[voronoi]") {
  // Points graded 1000:1 towards the origin's corner of the unit box (as seeds
  // round a wall), buckets of the finest size.
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  PointBuckets b({0, 0}, {1, 1}, 1e-3);
  CHECK(b.levels() == 11);  // 1e-3 * 2^10 > 1
  for (int k = 0; k < 4000; ++k) {
    const double r = std::pow(10.0, -3 * unit(gen)), a = 0.5 * M_PI * unit(gen);
    b.add({r * std::cos(a), r * std::sin(a)});
  }
  for (int query = 0; query < 200; ++query) {
    const Eigen::Vector2d p(unit(gen), unit(gen));
    const double r = std::pow(10.0, -3 * unit(gen));
    std::size_t near = 0, seen = 0, far = 0;
    for (const Eigen::Vector2d& q : b.points()) near += (q - p).norm() <= r;
    std::set<const Eigen::Vector2d*> visited;
    b.all_of_near(p, r, [&](const Eigen::Vector2d& q) {
      seen += (q - p).norm() <= r;
      // Cells of at most r (or the finest, 1e-3): a point scanned lies within
      // r + 2 sqrt(2) max(r, 1e-3).
      far += (q - p).norm() > r + 2 * std::sqrt(2.0) * std::max(r, 1e-3) + 1e-12;
      return true;
    });
    CAPTURE(p, r);
    CHECK(seen == near);
    CHECK(far == 0);
  }
  // f returning false stops the search.
  int calls = 0;
  CHECK_FALSE(b.all_of_near({0, 0}, 1.0, [&](const Eigen::Vector2d&) { return ++calls < 3; }));
  CHECK(calls == 3);
}

TEST_CASE("point buckets: at most 1024 cells a side, however fine the cell asked for",
          "[voronoi][seeding]") {
  // A 100:1 metric's smallest size asked 1e10 buckets of the seeding's unit
  // box: the finest level is 1 / 1024 wide, 11 levels up to the box.
  PointBuckets b({0, 0}, {1, 1}, 1e-7);
  CHECK(b.levels() == 11);
  b.add({0.5, 0.5});
  b.add({0.5 + 1e-6, 0.5});
  int seen = 0;
  b.all_of_near({0.5, 0.5}, 1e-7, [&](const Eigen::Vector2d&) { return ++seen > 0; });
  CHECK(seen == 2);
}
