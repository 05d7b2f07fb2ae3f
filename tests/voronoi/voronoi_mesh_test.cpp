// The Voronoi mesher as a C++ caller uses it, with no Gmsh: a square seeded
// by hand, meshed in constant metrics, checked for the properties of a
// conforming linear mesh and for sizes that follow the metric.
#include "voronoi/voronoi_mesh.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "core/error.h"

using homesh::MetricField;
using homesh::SeededBoundary;

namespace {

// The unit square, one surface (tag 1) bounded by four curves (tags 1-4,
// counter-clockwise), each seeded at n + 1 uniform points, corners on model
// points 1-4.
SeededBoundary unit_square(int n) {
  const Eigen::Vector2d corner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  SeededBoundary b;
  b.surfaces.push_back({1, {{{1, false}, {2, false}, {3, false}, {4, false}}}});
  b.seeds.resize(2, 4 * n);
  for (int c = 0; c < 4; ++c) {
    b.seeds.col(c) = corner[c];
    b.classes.push_back({0, c + 1, std::numeric_limits<double>::quiet_NaN()});
  }
  int next = 4;
  for (int c = 0; c < 4; ++c) {
    const Eigen::Vector2d a = corner[c], z = corner[(c + 1) % 4];
    std::vector<int> on{c};
    for (int k = 1; k < n; ++k) {
      b.seeds.col(next) = a + (z - a) * k / n;
      b.classes.push_back({1, c + 1, static_cast<double>(k) / n});
      on.push_back(next++);
    }
    on.push_back((c + 1) % 4);
    b.curve_seeds[c + 1] = on;
    Eigen::Matrix2Xd samples(2, 101);
    for (int k = 0; k <= 100; ++k) samples.col(k) = a + (z - a) * k / 100.0;
    b.curve_samples[c + 1] = samples;
  }
  return b;
}

double total_area(const homesh::Mesh& m) {
  double area = 0;
  for (Eigen::Index f = 0; f < m.tri.cols(); ++f) {
    const Eigen::Vector2d a = m.x.col(m.tri(0, f)), b = m.x.col(m.tri(1, f)),
                          c = m.x.col(m.tri(2, f));
    const double twice = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    REQUIRE(twice > 0);  // every triangle counter-clockwise
    area += 0.5 * twice;
  }
  return area;
}

}  // namespace

TEST_CASE("voronoi_mesh meshes a hand-seeded square conformingly, sized by the metric",
          "[voronoi]") {
  const int n = 10;  // boundary edges of 0.1
  const SeededBoundary b = unit_square(n);
  homesh::VoronoiReport rep;
  // Unit metric length = 0.1: M = 100 I.
  const homesh::Mesh m =
      homesh::voronoi_mesh(b, MetricField::constant(100 * Eigen::Matrix2d::Identity()), {}, &rep);
  CHECK(total_area(m) == Approx(1.0).epsilon(1e-12));
  CHECK(m.num_lines() == 4 * n);  // the boundary seeds' segments, every one in the mesh
  CHECK(rep.filled_triangles == 0);
  // Every triangle from the dual, but for the clean-up's merges (each removed node of valence
  // three or four leaves two triangles fewer).
  CHECK(rep.dual_triangles - 2 * (rep.valence_three + rep.valence_four) == m.num_triangles());
  // Unit equilateral triangles of side 0.1 tile the square in 1 / (sqrt(3)/4 0.01) = 231.
  CHECK(m.num_triangles() > 180);
  CHECK(m.num_triangles() < 300);
  for (std::size_t k = 0; k < b.classes.size(); ++k) {  // the boundary seeds come first, as given
    CHECK(m.x.col(static_cast<Eigen::Index>(k)) == b.seeds.col(static_cast<Eigen::Index>(k)));
    CHECK(m.node_class[k].dim == b.classes[k].dim);
  }
  for (std::size_t k = b.classes.size(); k < m.node_class.size(); ++k)
    CHECK(m.node_class[k].dim == 2);
}

TEST_CASE("voronoi_mesh names the seed file of a seed outside the domain", "[voronoi]") {
  const SeededBoundary b = unit_square(8);
  homesh::SeedList list;
  list.points.resize(2, 2);
  list.points << 0.5, 2.0, 0.5, 0.5;
  list.lines = {1, 4};
  homesh::VoronoiMeshOptions o;
  o.seed_list = &list;
  o.seed_path = "seeds.txt";
  REQUIRE_THROWS_WITH(
      homesh::voronoi_mesh(b, MetricField::constant(64 * Eigen::Matrix2d::Identity()), o),
      "seeds.txt:4: seed (2, 0.5) lies outside the domain");
}

namespace {

// The unit square graded along x: h(x) = 0.01 + 0.12 x, the boundary seeded
// at that spacing (the left side at 0.01, the right at 0.13).
SeededBoundary graded_square(double (*h)(double)) {
  std::vector<double> xs{0};
  while (xs.back() < 1) xs.push_back(xs.back() + h(xs.back()));
  const double stretch = 1 / xs.back();  // the last step onto x = 1
  for (double& x : xs) x *= stretch;
  const int nx = static_cast<int>(xs.size()) - 1;
  const int left = static_cast<int>(std::round(1 / h(0))),
            right = static_cast<int>(std::round(1 / h(1)));
  SeededBoundary b;
  b.surfaces.push_back({1, {{{1, false}, {2, false}, {3, false}, {4, false}}}});
  std::vector<Eigen::Vector2d> pts;
  const auto add = [&](const Eigen::Vector2d& p, homesh::NodeClass c) {
    pts.push_back(p);
    b.classes.push_back(c);
    return static_cast<int>(pts.size()) - 1;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector2d corner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int c = 0; c < 4; ++c) add(corner[c], {0, c + 1, nan});
  // Curve c from corner c to corner c + 1, at parameters t in (0, 1).
  const auto curve = [&](int c, const std::vector<double>& t) {
    const Eigen::Vector2d a = corner[c], z = corner[(c + 1) % 4];
    std::vector<int> on{c};
    for (const double u : t) on.push_back(add(a + (z - a) * u, {1, c + 1, u}));
    on.push_back((c + 1) % 4);
    b.curve_seeds[c + 1] = on;
    Eigen::Matrix2Xd samples(2, 401);
    for (int k = 0; k <= 400; ++k) samples.col(k) = a + (z - a) * k / 400.0;
    b.curve_samples[c + 1] = samples;
  };
  std::vector<double> bottom, top, side_r, side_l;
  for (int k = 1; k < nx; ++k) bottom.push_back(xs[k]);
  for (int k = nx - 1; k >= 1; --k) top.push_back(1 - xs[k]);
  for (int k = 1; k < right; ++k) side_r.push_back(static_cast<double>(k) / right);
  for (int k = 1; k < left; ++k) side_l.push_back(static_cast<double>(k) / left);
  curve(0, bottom);
  curve(1, side_r);
  curve(2, top);
  curve(3, side_l);
  b.seeds.resize(2, static_cast<Eigen::Index>(pts.size()));
  for (std::size_t k = 0; k < pts.size(); ++k) b.seeds.col(static_cast<Eigen::Index>(k)) = pts[k];
  return b;
}

// Mean ratio 4 sqrt(3) A / (sum of squared edges), 1 equilateral (Q11).
double mean_ratio_mean(const homesh::Mesh& m, double* worst) {
  double sum = 0;
  *worst = 1;
  for (Eigen::Index f = 0; f < m.tri.cols(); ++f) {
    const Eigen::Vector2d a = m.x.col(m.tri(0, f)), b = m.x.col(m.tri(1, f)),
                          c = m.x.col(m.tri(2, f));
    const double area = 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    const double q = 4 * std::sqrt(3.0) * area /
                     ((b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm());
    sum += q;
    *worst = std::min(*worst, q);
  }
  return sum / static_cast<double>(m.tri.cols());
}

}  // namespace

TEST_CASE(
    "voronoi_mesh grows the fine seeds of a graded square in windows, as well as on one "
    "fine grid",
    "[voronoi]") {
  double (*h)(double) = [](double x) { return 0.01 + 0.12 * x; };
  const SeededBoundary b = graded_square(h);
  const homesh::CartesianGrid coarse =
      homesh::CartesianGrid::spanning({-0.05, -0.05}, {1.05, 1.05}, 23, 23);
  std::vector<Eigen::Matrix2d> M(coarse.node_count());
  for (int j = 0; j < coarse.ny; ++j)
    for (int i = 0; i < coarse.nx; ++i) {
      const double hx = h(std::clamp(coarse.point(i, j).x(), 0.0, 1.0));
      M[coarse.index(i, j)] = Eigen::Matrix2d::Identity() / (hx * hx);
    }
  const MetricField metric(coarse, M);
  homesh::VoronoiMeshOptions o;
  o.lloyd.iterations = 4;
  o.dual = "grown";  // the isotropic metric would take the exact dual, no grid
  homesh::VoronoiReport windows, one_grid;
  const homesh::Mesh a = homesh::voronoi_mesh(b, metric, o, &windows);
  o.fine_windows = false;
  const homesh::Mesh c = homesh::voronoi_mesh(b, metric, o, &one_grid);
  const homesh::VoronoiSurfaceReport &w = windows.surfaces.at(0), &g = one_grid.surfaces.at(0);
  INFO("windows: grid " << w.grid.nx << ", " << w.fine_seeds << " fine seeds, " << w.fine_windows
                        << " + " << w.windows - w.fine_windows << " windows, " << a.num_triangles()
                        << " triangles; one grid " << g.grid.nx << ", " << c.num_triangles()
                        << " triangles");
  // The growth grid is sized for half the seeds, 6 cells per size (the median seed size here
  // is about 0.028), against 6 cells per 0.01 for the finest on one grid.
  CHECK(g.grid.nx >= 600);
  CHECK(w.grid.nx < 0.7 * g.grid.nx);
  CHECK(w.fine_seeds > 200);
  CHECK(w.fine_windows >= 1);
  CHECK(g.fine_seeds == 0);
  for (const homesh::Mesh* m : {&a, &c}) {
    CHECK(total_area(*m) == Approx(1.0).epsilon(1e-12));
    CHECK(m->num_lines() == static_cast<int>(b.classes.size()));
  }
  CHECK(windows.filled_triangles == 0);
  CHECK(one_grid.filled_triangles == 0);
  CHECK(std::abs(a.num_triangles() - c.num_triangles()) < 0.02 * c.num_triangles());
  double worst_a = 0, worst_c = 0;
  const double mean_a = mean_ratio_mean(a, &worst_a), mean_c = mean_ratio_mean(c, &worst_c);
  INFO("mean ratio: windows " << mean_a << " (worst " << worst_a << "), one grid " << mean_c
                              << " (worst " << worst_c << ")");
  CHECK(mean_a > mean_c - 0.005);
  CHECK(worst_a > 0.6);
}

TEST_CASE("voronoi_mesh: the front rows go round a hole as round the outer loop", "[voronoi]") {
  // The unit square with a square hole [0.35, 0.65]^2 whose loop runs
  // counter-clockwise as given (so the mesher turns it over), both seeded
  // every 0.05 in M = 400 I. Two rows, no Lloyd, no smoothing: the second
  // row stands sqrt 3 sizes off the walls, at the apexes of the first.
  SeededBoundary b = unit_square(20);
  const Eigen::Vector2d corner[4] = {{0.35, 0.35}, {0.65, 0.35}, {0.65, 0.65}, {0.35, 0.65}};
  const Eigen::Index first = b.seeds.cols();
  b.seeds.conservativeResize(2, first + 24);
  for (int c = 0; c < 4; ++c) {
    b.seeds.col(first + c) = corner[c];
    b.classes.push_back({0, c + 5, std::numeric_limits<double>::quiet_NaN()});
  }
  Eigen::Index next = first + 4;
  for (int c = 0; c < 4; ++c) {
    const Eigen::Vector2d a = corner[c], z = corner[(c + 1) % 4];
    std::vector<int> on{static_cast<int>(first + c)};
    for (int k = 1; k < 6; ++k) {
      b.seeds.col(next) = a + (z - a) * k / 6.0;
      b.classes.push_back({1, c + 5, k / 6.0});
      on.push_back(static_cast<int>(next++));
    }
    on.push_back(static_cast<int>(first + (c + 1) % 4));
    b.curve_seeds[c + 5] = on;
    Eigen::Matrix2Xd samples(2, 101);
    for (int k = 0; k <= 100; ++k) samples.col(k) = a + (z - a) * k / 100.0;
    b.curve_samples[c + 5] = samples;
  }
  b.surfaces[0].loops.push_back({{5, false}, {6, false}, {7, false}, {8, false}});
  homesh::VoronoiMeshOptions o;
  o.seeding.front_rows = 2;
  o.lloyd.iterations = 0;
  o.smooth = 0;
  o.cleanup = false;
  homesh::VoronoiReport rep;
  const homesh::Mesh m =
      homesh::voronoi_mesh(b, MetricField::constant(400 * Eigen::Matrix2d::Identity()), o, &rep);
  CHECK(total_area(m) == Approx(1.0 - 0.09).epsilon(1e-12));
  // Nodes sqrt(3) / 2 and sqrt 3 sizes (within 0.01 of a size) off the
  // hole's sides, beside them: the first and second rows (24 and 20 apexes
  // along the 24 segments, fewer at the corners). Before the hole's loop
  // was walked in order when turned over, its chains were single segments
  // and no second row grew (1 node there, from the Poisson-disc fill).
  int row1 = 0, row2 = 0;
  for (Eigen::Index k = first + 24; k < m.x.cols(); ++k) {
    const Eigen::Vector2d p = m.x.col(k) - Eigen::Vector2d(0.5, 0.5);
    const double d = p.cwiseAbs().maxCoeff() - 0.15;  // off the hole, along a side
    if (p.cwiseAbs().minCoeff() > 0.14) continue;     // not beside a side
    row1 += std::abs(d - 0.05 * std::sqrt(3.0) / 2) < 0.0005;
    row2 += std::abs(d - 0.05 * std::sqrt(3.0)) < 0.0005;
  }
  INFO(row1 << " " << row2);
  CHECK(row1 >= 16);
  CHECK(row2 >= 15);
}

TEST_CASE("voronoi_mesh: an isotropic metric takes the exact dual, the seeds' Delaunay triangles",
          "[voronoi]") {
  double (*h)(double) = [](double x) { return 0.02 + 0.08 * x; };
  const SeededBoundary b = graded_square(h);
  const homesh::CartesianGrid coarse =
      homesh::CartesianGrid::spanning({-0.05, -0.05}, {1.05, 1.05}, 23, 23);
  std::vector<Eigen::Matrix2d> iso(coarse.node_count()), aniso(coarse.node_count());
  for (int j = 0; j < coarse.ny; ++j)
    for (int i = 0; i < coarse.nx; ++i) {
      const double hx = h(std::clamp(coarse.point(i, j).x(), 0.0, 1.0));
      iso[coarse.index(i, j)] = Eigen::Matrix2d::Identity() / (hx * hx);
      aniso[coarse.index(i, j)] = Eigen::Vector2d(1 / (hx * hx), 0.25 / (hx * hx)).asDiagonal();
    }
  homesh::VoronoiMeshOptions o;
  o.smooth = 0;  // the dual's triangles as they are
  o.cleanup = false;
  o.raise_worst = 0;
  homesh::VoronoiReport rep;
  const homesh::Mesh m = homesh::voronoi_mesh(b, MetricField(coarse, iso), o, &rep);
  const homesh::VoronoiSurfaceReport& s = rep.surfaces.at(0);
  CHECK(s.exact_dual);
  CHECK(s.exact_lloyd);
  CHECK(s.filled == 0);
  CHECK(s.windows == 0);
  CHECK(total_area(m) == Approx(1.0).epsilon(1e-12));
  // Delaunay: no node inside a triangle's circumcircle (beyond round-off).
  int violations = 0;
  for (Eigen::Index f = 0; f < m.tri.cols(); ++f) {
    const Eigen::Vector2d a = m.x.col(m.tri(0, f)), p = m.x.col(m.tri(1, f)),
                          c = m.x.col(m.tri(2, f));
    const Eigen::Vector2d u = p - a, v = c - a;
    const double d = 2 * (u.x() * v.y() - u.y() * v.x());
    const Eigen::Vector2d centre =
        a + Eigen::Vector2d(v.y() * u.squaredNorm() - u.y() * v.squaredNorm(),
                            u.x() * v.squaredNorm() - v.x() * u.squaredNorm()) /
                d;
    const double r = (a - centre).norm();
    for (Eigen::Index k = 0; k < m.x.cols(); ++k)
      violations += (m.x.col(k) - centre).norm() < r * (1 - 1e-9);
  }
  CHECK(violations == 0);
  // An anisotropic metric takes the exact dual made Delaunay in the metric;
  // the option grows the crystals instead.
  homesh::VoronoiReport grown;
  homesh::voronoi_mesh(b, MetricField(coarse, aniso), o, &grown);
  CHECK(grown.surfaces.at(0).exact_dual);
  CHECK(grown.surfaces.at(0).metric_dual);
  o.dual = "grown";
  homesh::voronoi_mesh(b, MetricField(coarse, iso), o, &grown);
  CHECK_FALSE(grown.surfaces.at(0).exact_dual);
  o.dual = "Exact";
  CHECK_THROWS_WITH(homesh::voronoi_mesh(b, MetricField(coarse, iso), o),
                    "voronoi: the dual 'Exact' is none of exact, grown");
}
