// Boundary layers on open walls: chains of wall lines ending on a non-wall
// boundary (the floor and ceiling of a channel, a trapezoid's base).
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <utility>

#include "../layers/layer_test_meshes.h"
#include "layers/insert_layers.h"
#include "layers/wall_loops.h"
#include "quality/mesh_validity.h"

using namespace homesh;

namespace {

// [0, 4] x [0, 1] in 16 x 6 cells.
Mesh channel() {
  return test::channel_mesh(16, 6, [](double s, double t) { return Eigen::Vector2d(4 * s, t); });
}

// Base [0, 2] on y = 0, top [a, 2 + b] on y = 1, in 8 x 4 cells: domain angles
// atan2(1, a) at (0, 0) and pi - atan2(1, b) at (2, 0).
Mesh trapezoid(double a, double b) {
  return test::channel_mesh(8, 4, [=](double s, double t) {
    return Eigen::Vector2d((1 - t) * 2 * s + t * (a + s * (2 + b - a)), t);
  });
}

int lines_on(const Mesh& m, int curve) {
  return static_cast<int>(std::count(m.line_entity.begin(), m.line_entity.end(), curve));
}

// Edges bounding one triangle that are not lines, plus lines not bounding one
// triangle: 0 for a conforming boundary.
int boundary_mismatch(const Mesh& m) {
  std::map<std::pair<int, int>, int> count;
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int i = 0; i < 3; ++i) {
      const int a = m.tri(i, e), b = m.tri((i + 1) % 3, e);
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  int bad = 0, boundary = 0;
  for (const auto& [edge, c] : count) boundary += c == 1 ? 1 : 0;
  for (int k = 0; k < m.num_lines(); ++k) {
    const int a = m.line(0, k), b = m.line(1, k);
    const auto it = count.find({std::min(a, b), std::max(a, b)});
    bad += it == count.end() || it->second != 1 ? 1 : 0;
  }
  return bad + std::abs(boundary - m.num_lines());
}

}  // namespace

TEST_CASE("an open wall chains from one non-wall boundary line to another", "[layers]") {
  const Mesh m = channel();
  const auto loops = wall_loops(m, wall_curves(m, {"wall"}));
  REQUIRE(loops.size() == 1);
  const WallLoop& w = loops[0];
  CHECK_FALSE(w.closed);
  CHECK(w.size() == 17);
  CHECK(w.edges() == 16);
  CHECK(w.nodes.front() == 0);
  CHECK(w.nodes.back() == 16);
  CHECK(w.prev(0) == 17);        // (0, 1/6) on the inlet
  CHECK(w.next(16) == 16 + 17);  // (4, 1/6) on the outlet
  CHECK(m.line_entity[w.end_lines[0]] == 4);
  CHECK(m.line_entity[w.end_lines[1]] == 2);
  CHECK(w.curves.back() == 2);
  const auto normals = wall_normals(m, w);
  CHECK((normals.front().directions[0] - Eigen::Vector2d(0, 1)).norm() == 0);
  CHECK((normals.back().directions[0] - Eigen::Vector2d(0, 1)).norm() == 0);
  CHECK(normals.front().scale == Approx(1).epsilon(1e-15));

  // The floor and the ceiling of a channel one cell high end on the same inlet line.
  const Mesh thin =
      test::channel_mesh(4, 1, [](double s, double t) { return Eigen::Vector2d(4 * s, t); });
  CHECK_THROWS_WITH(wall_loops(thin, wall_curves(thin, {"wall", "top"})),
                    Catch::Contains("ends two open walls"));
  // Without the inlet's lines the wall ends on no boundary line.
  Mesh bare = m;
  int kept = 0;
  for (int k = 0; k < m.num_lines(); ++k)
    if (m.line_entity[k] != 4) {
      bare.line.col(kept) = m.line.col(k);
      bare.line_entity[kept++] = m.line_entity[k];
    }
  bare.line.conservativeResize(2, kept);
  bare.line_entity.resize(kept);
  CHECK_THROWS_WITH(wall_loops(bare, {1}), Catch::Contains("on 0 other boundary lines"));
}

TEST_CASE("layers on the floor of a channel end on the inlet and outlet", "[layers]") {
  const Mesh m = channel();
  const int n = 4, e = 16;
  const LayerResult r = insert_layers(m, test::layer_options({"wall"}, n, 0.01, 1.3));
  const Mesh& b = r.mesh;
  CHECK(r.loops == 1);
  CHECK(r.open_walls == 1);
  CHECK(r.wall_edges == e);
  CHECK(b.num_triangles() == m.num_triangles() + 2 * n * e);
  CHECK(b.num_nodes() == m.num_nodes() + n * (e + 1));
  CHECK(b.num_lines() == m.num_lines() + 2 * n);
  CHECK(lines_on(b, 4) == 6 + n);
  CHECK(lines_on(b, 2) == 6 + n);
  CHECK(lines_on(b, 1) == e);
  CHECK(boundary_mismatch(b) == 0);
  CHECK(mesh_validity(b).invalid == 0);
  for (int k = 1; k <= n; ++k) CHECK(std::count(r.layer.begin(), r.layer.end(), k) == 2 * e);
  CHECK(b.physicals.size() == m.physicals.size());
  CHECK(b.point_node == m.point_node);

  // Depth d_k at every wall node, the ends included, exactly on x = 0 and x = 4.
  const auto d = layer_depths(0.01, 1.3, n);
  REQUIRE(static_cast<int>(r.lines.size()) == e + 1);
  for (const LayerLine& line : r.lines) {
    const Eigen::Vector2d w = b.x.col(line.wall_node);
    for (int k = 1; k <= n; ++k) {
      const Eigen::Vector2d p = b.x.col(line.nodes[k]);
      CHECK(p(1) == Approx(d[k]).epsilon(1e-14));
      CHECK(std::abs(p(0) - w(0)) < 1e-15);
      const NodeClass& c = b.node_class[line.nodes[k]];
      if (w(0) == 0 || w(0) == 4) {
        CHECK(p(0) == w(0));
        CHECK(c.dim == 1);
        CHECK(c.tag == (w(0) == 0 ? 4 : 2));
      } else {
        CHECK(c.dim == 2);
      }
    }
  }
}

TEST_CASE("an open wall's ends thin where the boundary's first edge is short", "[layers]") {
  // The inlet's and outlet's first edges are 1/6 high: the end normals slide along
  // them and may take 0.4 / 6 of the stack's 0.2 (4 x 0.05), a third, tapering
  // back to the full stack within two wall edges.
  const Mesh m = channel();
  const LayerResult r = insert_layers(m, test::layer_options({"wall"}, 4, 0.05, 1));
  CHECK(mesh_validity(r.mesh).invalid == 0);
  REQUIRE(r.thinned.size() == 2);
  for (const ThinnedLayers& t : r.thinned) {
    CHECK(t.factor == Approx(1.0 / 3).epsilon(1e-12));
    CHECK(t.gap == Approx(1.0 / 6).epsilon(1e-12));
    CHECK((t.tightest(0) == 0 || t.tightest(0) == 4));
    CHECK(t.tightest(1) == 0);
    CHECK(t.lines == 2);
  }
  for (const LayerLine& line : r.lines) {
    const Eigen::Vector2d w = r.mesh.x.col(line.wall_node);
    const double depth = r.mesh.x(1, line.nodes.back());
    if (w(0) == 0 || w(0) == 4) CHECK(depth == Approx(0.4 / 6).epsilon(1e-12));
    if (w(0) == 2) CHECK(depth == Approx(0.2).epsilon(1e-12));
  }
}

TEST_CASE("layers on the floor and ceiling of a channel: two open walls", "[layers]") {
  const Mesh m = channel();
  const int n = 5, e = 16;
  const LayerResult r = insert_layers(m, test::layer_options({"wall", "top"}, n, 0.005, 1.4));
  const Mesh& b = r.mesh;
  CHECK(r.loops == 2);
  CHECK(r.open_walls == 2);
  CHECK(r.wall_edges == 2 * e);
  CHECK(b.num_triangles() == m.num_triangles() + 2 * n * 2 * e);
  CHECK(b.num_nodes() == m.num_nodes() + n * 2 * (e + 1));
  CHECK(lines_on(b, 4) == 6 + 2 * n);
  CHECK(lines_on(b, 2) == 6 + 2 * n);
  CHECK(boundary_mismatch(b) == 0);
  CHECK(mesh_validity(b).invalid == 0);
  const auto d = layer_depths(0.005, 1.4, n);
  int ends = 0;
  for (const LayerLine& line : r.lines) {
    const Eigen::Vector2d w = b.x.col(line.wall_node);
    const double depth = std::abs(b.x(1, line.nodes[n]) - w(1));
    CHECK(depth == Approx(d[n]).epsilon(1e-14));
    if (w(0) == 0 || w(0) == 4) {
      ++ends;
      for (int k = 1; k <= n; ++k) CHECK(b.x(0, line.nodes[k]) == w(0));
    }
  }
  CHECK(ends == 4);
}

TEST_CASE("open walls meeting their neighbours at acute and obtuse angles", "[layers]") {
  // 63.4 deg at (0, 0) and 116.6 deg at (2, 0): s = 1 / sin keeps depth d_k.
  const Mesh m = trapezoid(0.5, 0.5);
  const int n = 4, e = 8;
  const LayerResult r = insert_layers(m, test::layer_options({"wall"}, n, 0.01, 1.2));
  const Mesh& b = r.mesh;
  CHECK(b.num_triangles() == m.num_triangles() + 2 * n * e);
  CHECK(boundary_mismatch(b) == 0);
  CHECK(mesh_validity(b).invalid == 0);
  const auto d = layer_depths(0.01, 1.2, n);
  const Eigen::Vector2d left(0.5, 1), right(0.5, 1);  // side directions from the base
  for (const LayerLine& line : r.lines) {
    const Eigen::Vector2d w = b.x.col(line.wall_node);
    for (int k = 1; k <= n; ++k) CHECK(b.x(1, line.nodes[k]) == Approx(d[k]).epsilon(1e-13));
    if (w(0) == 0 || w(0) == 2) {
      CHECK(line.scale == Approx(std::sqrt(1.25)).epsilon(1e-14));
      const Eigen::Vector2d side = w(0) == 0 ? left : right;
      for (int k = 1; k <= n; ++k) {
        const Eigen::Vector2d p = b.x.col(line.nodes[k]) - w;
        CHECK(std::abs(p(0) * side(1) - p(1) * side(0)) < 1e-15);  // on the side line
      }
    }
  }
  // 161.6 deg at (2, 0): the layers cannot end along that side.
  CHECK_THROWS_WITH(insert_layers(trapezoid(0, 3), test::layer_options({"wall"}, n, 0.01, 1.2)),
                    Catch::Contains("max_end_angle"));
}
