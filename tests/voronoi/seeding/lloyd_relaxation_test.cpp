#include "voronoi/seeding/lloyd_relaxation.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "../voronoi_test_support.h"
#include "voronoi/engines/voronoi_engines.h"

using namespace homesh;

namespace {

// The CVT energy of the regions of `seeds` grown on g: sum over the grid
// nodes x of |x - z_s|^2 in M(x), times the cell area.
double cvt_energy(const VoronoiProblem& p) {
  const CartesianGrid& g = p.grid;
  const Eigen::VectorXi labels = grow_crystals(p, "fast_marching").labels;
  double e = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const int s = labels(g.index(i, j));
      const Eigen::Vector2d v = g.point(i, j) - p.seeds.col(s);
      e += v.dot(p.metric.metric_at(g.point(i, j)) * v) * g.dx * g.dy;
    }
  return e;
}

}  // namespace

TEST_CASE("region centroids: plain in a constant metric, weighted by M(x) in a field",
          "[voronoi][lloyd]") {
  const CartesianGrid g = CartesianGrid::spanning({0, 0}, {1, 1}, 101, 101);
  // Left half region 0, right half region 1; region 2 empty.
  Eigen::VectorXi labels(g.node_count());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) labels(g.index(i, j)) = i <= 50 ? 0 : 1;
  const MetricField aniso = MetricField::constant(metric_from_axes(0.3, 0.1, 0.01));
  Eigen::Matrix2Xd z = region_centroids(g, labels, 3, aniso);
  CHECK(z(0, 0) == Approx(0.25));
  CHECK(z(1, 0) == Approx(0.5));
  CHECK(z(0, 1) == Approx(0.755));
  CHECK(z(1, 1) == Approx(0.5));
  CHECK(std::isnan(z(0, 2)));

  // M(x) = (1 + x) I on a coarse grid equal to the fine one (Shepard is then
  // exact at the nodes), weight sqrt(det M) M = (1 + x)^2 I: the centroid of
  // [0, 1]^2 in x is int x (1 + x)^2 / int (1 + x)^2 = 17/28, to O(dx) with
  // equal node weights.
  std::vector<Eigen::Matrix2d> M(g.node_count());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      M[g.index(i, j)] = (1.0 + g.point(i, j).x()) * Eigen::Matrix2d::Identity();
  labels.setZero();
  z = region_centroids(g, labels, 1, MetricField(g, M));
  CHECK(z(0, 0) == Approx(17.0 / 28.0).margin(0.005));
  CHECK(z(1, 0) == Approx(0.5));
}

TEST_CASE("Lloyd's iteration lowers the CVT energy and keeps the fixed seeds", "[voronoi][lloyd]") {
  for (const Eigen::Matrix2d& M :
       {Eigen::Matrix2d(Eigen::Matrix2d::Identity()), metric_from_axes(0.5, 1.0, 0.25)}) {
    VoronoiProblem p;
    p.grid = CartesianGrid::spanning({0, 0}, {1, 1}, 161, 161);
    p.metric = MetricField::constant(M);
    p.seeds = test::uniform_seeds(40, 7, 0.05, 0.95);
    const double before = cvt_energy(p);
    LloydOptions o;
    o.iterations = 1;
    VoronoiProblem once = p;
    once.seeds = lloyd_relaxation(p, 4, "fast_marching", o);
    o.iterations = 10;
    VoronoiProblem ten = p;
    ten.seeds = lloyd_relaxation(p, 4, "fast_marching", o);
    const double after_one = cvt_energy(once), after_ten = cvt_energy(ten);
    INFO("energy " << before << " -> " << after_one << " -> " << after_ten);
    CHECK(after_one < 0.8 * before);
    CHECK(after_ten < 0.9 * after_one);
    CHECK(ten.seeds.leftCols(4) == p.seeds.leftCols(4));
    // Towards a centroidal tessellation: the seeds' largest distance to their
    // region's centroid shrinks.
    const auto far = [](const VoronoiProblem& q) {
      const Eigen::Matrix2Xd z =
          region_centroids(q.grid, grow_crystals(q, "fast_marching").labels, 40, q.metric);
      double d = 0.0;
      for (int s = 4; s < 40; ++s) d = std::max(d, (z.col(s) - q.seeds.col(s)).norm());
      return d;
    };
    const double far_one = far(once), far_ten = far(ten);
    INFO("largest distance to the centroid " << far_one << " -> " << far_ten);
    CHECK(far_ten < 0.5 * far_one);
    CHECK(far_ten < 4.0 * p.grid.dx);
  }
}

TEST_CASE("Lloyd's iteration keeps the held seeds and refuses a wrong count of flags",
          "[voronoi][lloyd]") {
  VoronoiProblem p;
  p.grid = CartesianGrid::spanning({0, 0}, {1, 1}, 81, 81);
  p.seeds = test::uniform_seeds(20, 3, 0.05, 0.95);
  std::vector<char> held(20, 0);
  for (int s = 0; s < 20; s += 3) held[s] = 1;
  LloydOptions o;
  o.iterations = 3;
  const Eigen::Matrix2Xd moved = lloyd_relaxation(p, 2, "fast_marching", o, held);
  int kept = 0, free_moved = 0;
  for (int s = 0; s < 20; ++s) {
    const bool same = moved.col(s) == p.seeds.col(s);
    if (s < 2 || held[s])
      kept += same;
    else
      free_moved += !same;
  }
  CHECK(kept == 2 + 6);  // seeds 0, 1 and the held 3, 6, ..., 18 (0 counted once)
  CHECK(free_moved > 8);
  REQUIRE_THROWS_WITH(lloyd_relaxation(p, 2, "fast_marching", o, std::vector<char>(19, 0)),
                      "voronoi: 19 held flags for 20 seeds");
}
