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
  CHECK(rep.dual_triangles == m.num_triangles());
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
