#include "layers/insert_layers.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "../layers/layer_test_meshes.h"
#include "core/error.h"
#include "core/raise_order.h"
#include "layers/radius_ratio.h"
#include "quality/mesh_validity.h"

using namespace homesh;

namespace {

Mesh annulus(double outer = 3, int rings = 6) {
  return test::ring_mesh(test::circle(32, 1), test::circle(32, outer), rings, 1.5);
}

// An L of 4 x 4 cells (spacing 0.25) without its upper-right 2 x 2 block: a
// re-entrant corner at (0.5, 0.5) and five right-angle corners, all on the wall.
Mesh l_shape() {
  return test::grid_mesh(
      4, 4, 0.25, [](int i, int j) { return i < 2 || j < 2; },
      [](const Eigen::Vector2d&) { return true; });
}

// A 8 x 8 box (spacing 0.25) with a 4 x 4 square hole: walls "wall" (hole) and "outer".
Mesh box_with_hole() {
  return test::grid_mesh(
      8, 8, 0.25, [](int i, int j) { return !(i >= 2 && i < 6 && j >= 2 && j < 6); },
      [](const Eigen::Vector2d& p) {
        return p(0) > 0.4 && p(0) < 1.6 && p(1) > 0.4 && p(1) < 1.6;
      });
}

// A rhombus with 17 deg tips (domain angle 343 deg) in a circle of radius 3.
Mesh rhombus_hole() {
  const Eigen::Matrix2Xd inner = test::rhombus(10, 0.15);
  Eigen::Matrix2Xd outer(2, inner.cols());
  for (int i = 0; i < inner.cols(); ++i) {
    const double a = 2 * M_PI * i / inner.cols();
    outer.col(i) = 3 * Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  return test::ring_mesh(inner, outer, 10);
}

double worst_q(const Mesh& m, const std::vector<int>& tris) {
  const Eigen::VectorXd q = radius_ratios(m);
  double w = 1;
  for (int e : tris) w = std::min(w, q(e));
  return w;
}

}  // namespace

TEST_CASE("layer depths grow geometrically and sum to first (r^n - 1) / (r - 1)", "[layers]") {
  const auto d = layer_depths(1e-3, 1.2, 15);
  REQUIRE(d.size() == 16);
  CHECK(d[0] == 0);
  CHECK(d[15] == Approx(1e-3 * (std::pow(1.2, 15) - 1) / 0.2).epsilon(1e-13));
  for (int k = 2; k <= 15; ++k) CHECK((d[k] - d[k - 1]) / (d[k - 1] - d[k - 2]) == Approx(1.2));
  CHECK(layer_depths(0.1, 1, 3).back() == Approx(0.3));
  CHECK_THROWS_WITH(layer_depths(0, 1.2, 3), Catch::Contains("thickness must be > 0"));
  CHECK_THROWS_WITH(layer_depths(1e-3, 1.2, 0), Catch::Contains("n must be in"));
}

TEST_CASE("layers around a circular hole: counts, depths, walls kept, valid", "[layers]") {
  const Mesh m = annulus();
  const int n = 3;
  const LayerResult r = insert_layers(m, test::layer_options({"wall"}, n, 0.02, 1.5));
  const Mesh& b = r.mesh;
  const int e = 32;
  CHECK(r.loops == 1);
  CHECK(r.wall_edges == e);
  CHECK(r.fan_nodes == 0);
  // The first ring (depth 2 * (1/6)^1.5 = 0.136) lies beyond 1.2 times the
  // stack's depth 0.095: no node is in the room, none removed.
  CHECK(r.cleared == 0);
  CHECK(r.thinned.empty());
  CHECK(b.num_triangles() == m.num_triangles() + 2 * n * e);
  CHECK(b.num_nodes() == m.num_nodes() + n * e);
  CHECK(r.thickness == Approx(0.02 * (1 + 1.5 + 2.25)));
  CHECK(mesh_validity(b).invalid == 0);

  // Each normal line: the wall node, then the interfaces at d_k * scale, radially.
  const auto d = layer_depths(0.02, 1.5, n);
  REQUIRE(static_cast<int>(r.lines.size()) == e);
  for (const LayerLine& line : r.lines) {
    REQUIRE(static_cast<int>(line.nodes.size()) == n + 1);
    CHECK(line.nodes[0] == line.wall_node);
    const Eigen::Vector2d w = b.x.col(line.wall_node);
    CHECK((line.direction - w.normalized()).norm() < 1e-14);
    for (int k = 1; k <= n; ++k)
      CHECK((b.x.col(line.nodes[k]) - w).norm() ==
            Approx(d[k] / std::cos(M_PI / 32)).epsilon(1e-12));
  }
  // Layer k holds 2 E triangles; the input's triangles come first.
  for (int k = 0; k <= n; ++k)
    CHECK(std::count(r.layer.begin(), r.layer.end(), k) == (k == 0 ? m.num_triangles() : 2 * e));
  for (int t = 0; t < m.num_triangles(); ++t) CHECK(r.layer[t] == 0);

  // The walls keep nodes, positions, classification and lines; new nodes are interior.
  CHECK(b.line == m.line);
  CHECK(b.line_entity == m.line_entity);
  CHECK(b.physicals.size() == m.physicals.size());
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_class[i].dim < 2) {
      CHECK(b.node_class[i].dim == m.node_class[i].dim);
      CHECK(b.node_class[i].u == m.node_class[i].u);
      CHECK((b.x.col(i) - m.x.col(i)).norm() == 0);
    }
  for (int i = m.num_nodes(); i < b.num_nodes(); ++i) CHECK(b.node_class[i].dim == 2);
  for (int t = 0; t < b.num_triangles(); ++t) CHECK(b.tri_entity[t] == 1);
}

TEST_CASE("layers on several walls: concave and convex corners of a box with a hole", "[layers]") {
  // The corners on CAD points (node class dim 0), as Gmsh classifies a box's: the
  // normals there and beside them are not blended (wall_normals.h).
  Mesh m = box_with_hole();
  for (int v = 0; v < m.num_nodes(); ++v) {
    const Eigen::Vector2d p = m.x.col(v);
    const bool outer = (p(0) == 0 || p(0) == 2) && (p(1) == 0 || p(1) == 2);
    const bool hole = (p(0) == 0.5 || p(0) == 1.5) && (p(1) == 0.5 || p(1) == 1.5);
    if (outer || hole) m.node_class[v] = {0, 1};
  }
  const int n = 4;
  const LayerResult r = insert_layers(m, test::layer_options({"wall", "outer"}, n, 0.005, 1.3));
  CHECK(r.loops == 2);
  CHECK(r.wall_edges == 16 + 32);
  CHECK(r.mesh.num_triangles() == m.num_triangles() + 2 * n * 48);
  CHECK(mesh_validity(r.mesh).invalid == 0);
  // The corner nodes go along the diagonals by sqrt 2 d_n, keeping d_n from both sides.
  for (const LayerLine& line : r.lines) {
    const Eigen::Vector2d w = r.mesh.x.col(line.wall_node), f = r.mesh.x.col(line.nodes[n]);
    const bool corner = std::abs(line.direction(0) * line.direction(1)) > 0.1;
    CHECK((f - w).norm() == Approx((corner ? std::sqrt(2) : 1) * r.thickness));
    if (corner) CHECK((f - w).cwiseAbs().minCoeff() == Approx(r.thickness));
  }
}

TEST_CASE("layers at a re-entrant corner and five right-angle corners", "[layers]") {
  const Mesh m = l_shape();
  const int n = 3;
  const LayerResult r = insert_layers(m, test::layer_options({"wall"}, n, 0.01, 1.5));
  CHECK(r.wall_edges == 16);
  CHECK(r.mesh.num_triangles() == m.num_triangles() + 2 * n * 16);
  CHECK(r.sharpest_angle == Approx(1.5 * M_PI));
  CHECK((r.mesh.x.col(r.sharpest_node) - Eigen::Vector2d(0.5, 0.5)).norm() < 1e-15);
  CHECK(mesh_validity(r.mesh).invalid == 0);
  // The front of the re-entrant corner stands d_n from both walls, away from the notch.
  for (const LayerLine& line : r.lines)
    if (line.wall_node == r.sharpest_node)
      CHECK((r.mesh.x.col(line.nodes[n]) - Eigen::Vector2d(0.5 - r.thickness, 0.5 - r.thickness))
                .norm() < 1e-12);
}

TEST_CASE("fans of normals: counts and validity at the corners of a square hole", "[layers]") {
  const Mesh m = box_with_hole();
  LayerOptions o = test::layer_options({"wall"}, 3, 0.01, 1.2);
  o.normals.multi = true;
  o.normals.fan_angle = 270;
  for (int fan : {3, 5}) {
    o.normals.fan = fan;
    const LayerResult r = insert_layers(m, o);
    CHECK(r.fan_nodes == 4);
    CHECK(r.gap_triangles == 4 * (fan - 1));
    CHECK(static_cast<int>(r.lines.size()) == 16 + 4 * (fan - 1));
    CHECK(r.mesh.num_triangles() == m.num_triangles() + 2 * 3 * 16 + 2 * 3 * (fan - 1) * 4);
    CHECK(r.mesh.num_nodes() == m.num_nodes() + 3 * static_cast<int>(r.lines.size()));
    CHECK(mesh_validity(r.mesh).invalid == 0);
    // Equidistant: every fan node at depth d_k from its corner.
    for (const LayerLine& line : r.lines)
      if (line.scale == 1 && std::abs(line.direction(0) * line.direction(1)) > 1e-9)
        CHECK((r.mesh.x.col(line.nodes[3]) - r.mesh.x.col(line.wall_node)).norm() ==
              Approx(r.thickness));
  }
}

TEST_CASE("multiple normals beat a single normal at a sharp corner (Eq 4.17)", "[layers]") {
  const Mesh m = rhombus_hole();
  LayerOptions o = test::layer_options({"wall"}, 4, 0.004, 1.2);
  const LayerResult single = insert_layers(m, o);
  o.normals.multi = true;
  const LayerResult multi = insert_layers(m, o);
  REQUIRE(single.sharpest_angle == Approx(2 * M_PI - 2 * std::atan(0.15)));
  REQUIRE(multi.fan_nodes == 2);  // the two sharp tips
  CHECK(multi.mesh.num_triangles() == single.mesh.num_triangles() + 2 * 2 * 4 * 4);
  const double qs = worst_q(single.mesh, corner_triangles(single, single.sharpest_node));
  const double qm = worst_q(multi.mesh, corner_triangles(multi, multi.sharpest_node));
  CHECK(corner_triangles(single, single.sharpest_node).size() == 4 * 4);
  // Both wall-edge strips, plus the fan's (m - 1)(2 n - 1) (its gap triangles are not layers).
  CHECK(corner_triangles(multi, multi.sharpest_node).size() == 4 * 4 + 4 * 7);
  CHECK(qs < 0.01);  // the single normal's skewed quads at the tip
  CHECK(qm > 0.07);  // the fan's worst: a wall-edge strip of aspect 0.1 / 0.004
  CHECK(qm > 10 * qs);
  CHECK(mesh_validity(multi.mesh).invalid == 0);
}

TEST_CASE("layers clear the nodes in the room: counts, walls kept, valid", "[layers]") {
  // 12 rings graded 1.5 to radius 3: the first three (depths 0.046, 0.13, 0.24)
  // lie within 1.2 times the stack's 0.21 (n = 6, first 0.02, ratio 1.2).
  const Mesh m = annulus(3, 12);
  const int n = 6, e = 32;
  const LayerResult r = insert_layers(m, test::layer_options({"wall"}, n, 0.02, 1.2));
  CHECK(r.cleared >= 2 * e);
  CHECK(r.cleared <= 3 * e);
  // Each collapse takes the two triangles of an edge with a node.
  CHECK(r.mesh.num_triangles() == m.num_triangles() - 2 * r.cleared + 2 * n * e);
  CHECK(r.mesh.num_nodes() == m.num_nodes() - r.cleared + n * e);
  CHECK(std::count(r.layer.begin(), r.layer.end(), 0) == m.num_triangles() - 2 * r.cleared);
  CHECK(mesh_validity(r.mesh).invalid == 0);
  CHECK(r.mesh.line == m.line);
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_class[i].dim < 2) CHECK((r.mesh.x.col(i) - m.x.col(i)).norm() == 0);

  // Solved on the whole mesh (reach 0), the removed nodes held: the same room.
  LayerOptions whole = test::layer_options({"wall"}, n, 0.02, 1.2);
  whole.room.reach = 0;
  const LayerResult w = insert_layers(m, whole);
  CHECK(w.cleared == r.cleared);
  CHECK(mesh_validity(w.mesh).invalid == 0);
}

TEST_CASE("layers thin the stack in a narrow gap and say by how much", "[layers]") {
  // A hole of radius 1 centred at (0.8, 0) in a circle of radius 3: along +x the
  // gap is 1.2, along -x 2.8. A stack 1 deep (4 layers of 0.25) may take
  // fill = 0.4 of the gap: 0.48 along +x, where the miter s = 1 / cos(pi / 32)
  // scales the depth, so the layers there are thinned by 0.48 cos(pi / 32); the
  // full stack fits along -x.
  const Mesh m =
      test::ring_mesh(test::circle(32, 1, Eigen::Vector2d(0.8, 0)), test::circle(32, 3), 8, 1.5);
  const LayerResult r = insert_layers(m, test::layer_options({"wall"}, 4, 0.25, 1));
  CHECK(mesh_validity(r.mesh).invalid == 0);
  REQUIRE(r.thinned.size() == 1);
  const ThinnedLayers& t = r.thinned[0];
  CHECK((t.tightest - Eigen::Vector2d(1.8, 0)).norm() < 1e-12);
  CHECK(t.factor == Approx(0.48 * std::cos(M_PI / 32)).epsilon(1e-12));
  CHECK(t.gap == Approx(1.2).epsilon(1e-12));
  CHECK(t.facing == 2);
  CHECK(t.lines > 1);
  CHECK(t.lines < 32);
  for (const LayerLine& line : r.lines) {
    const Eigen::Vector2d w = r.mesh.x.col(line.wall_node);
    const double depth = (r.mesh.x.col(line.nodes.back()) - w).norm();
    if ((w - Eigen::Vector2d(1.8, 0)).norm() < 1e-12) CHECK(depth == Approx(0.48).epsilon(1e-12));
    if ((w - Eigen::Vector2d(-0.2, 0)).norm() < 1e-12)
      CHECK(depth == Approx(1 / std::cos(M_PI / 32)).epsilon(1e-12));
  }
}

TEST_CASE("layers thin the stack where a concave wall makes the normals cross", "[layers]") {
  // The domain inside the flower r = 3 + 0.6 cos(6 theta) (96 nodes, walls
  // "outer") round a hole of radius 0.3. At the six lobe tips the wall's radius of
  // curvature is r^2 / (r^2 - r r'') = 3.6^2 / (3.6^2 + 3.6 * 21.6) = 0.514: the
  // normals cross about that deep, so a stack 0.75 deep (6 x 0.125) folds there.
  // With cross = 0.6 it takes 0.6 of the crossing depth at the tips, thinned.
  Eigen::Matrix2Xd flower(2, 96);
  for (int i = 0; i < 96; ++i) {
    const double a = 2 * M_PI * i / 96, r = 3 + 0.6 * std::cos(6 * a);
    flower.col(i) = r * Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  const Mesh m = test::ring_mesh(test::circle(96, 0.3), flower, 10);
  LayerOptions o = test::layer_options({"outer"}, 6, 0.125, 1);
  const LayerResult r = insert_layers(m, o);
  CHECK(mesh_validity(r.mesh).invalid == 0);
  // (The troughs, r = 2.4, are 2.1 from the hole: room for 0.84 there, no thinning.)
  REQUIRE(r.thinned.size() == 6);
  for (const ThinnedLayers& t : r.thinned) {
    CHECK(t.crossing);
    CHECK(t.facing == -1);
    CHECK(std::abs(t.tightest.norm() - 3.6) < 0.1);  // at a lobe tip
    CHECK(t.gap == Approx(0.514).margin(0.07));      // the discrete crossing depth
    CHECK(t.factor > 0.4);                           // 0.6 * 0.514 / 0.75 = 0.41
    CHECK(t.factor < 0.5);
  }
  // Taking the whole crossing depth, the cells at the tips fold.
  o.cross = 0.999;
  CHECK_THROWS_WITH(insert_layers(m, o), Catch::Contains("fold") || Catch::Contains("room"));
  // A first layer deeper than cross times the crossing depth fails at once.
  o.cross = 0.6;
  o.layers = 1;
  o.first = 0.4;
  CHECK_THROWS_WITH(insert_layers(m, o), Catch::Contains("neighbouring normals cross") &&
                                             Catch::Contains("cross = 0.6"));
}

TEST_CASE("layers refuse at once where not even the first layer fits", "[layers]") {
  // Gap 0.5 between the circles of radius 1 and 1.5: room for 0.4 * 0.5 = 0.2,
  // less than a first layer of 0.25 (times the miter 1 / cos(pi / 32)).
  const Mesh m = annulus(1.5, 3);
  CHECK_THROWS_WITH(insert_layers(m, test::layer_options({"wall"}, 1, 0.25, 1)),
                    Catch::Contains("no layer fits at the wall node") &&
                        Catch::Contains("curve 2 is 0.5 away") &&
                        Catch::Contains("first = 0.099 would fit"));
  // A stack of 6 x 0.1 = 0.6 is thinned to 0.2 all round instead.
  const LayerResult r = insert_layers(m, test::layer_options({"wall"}, 6, 0.1, 1));
  REQUIRE(r.thinned.size() == 1);
  CHECK(r.thinned[0].lines == 32);
  CHECK(r.thinned[0].factor == Approx(0.2 / 0.6 * std::cos(M_PI / 32)).epsilon(1e-12));
  CHECK(mesh_validity(r.mesh).invalid == 0);
  CHECK_THROWS_WITH(insert_layers(m, test::layer_options({"hull"}, 3, 0.01, 1.2)),
                    Catch::Contains("no wall 'hull'"));
  LayerOptions o = test::layer_options({"wall"}, 3, 0.01, 1.2);
  o.normals.multi = true;
  o.normals.fan = 2;
  CHECK_THROWS_WITH(insert_layers(m, o), Catch::Contains("odd"));
}

TEST_CASE("a quadratic mesh is layered on its corners", "[layers]") {
  const Mesh m = annulus();
  const LayerOptions o = test::layer_options({"wall"}, 2, 0.02, 1.2);
  const LayerResult linear = insert_layers(m, o);
  const LayerResult quadratic = insert_layers(raise_order(m, 2), o);
  CHECK(!linear.from_corners);
  CHECK(quadratic.from_corners);
  CHECK(quadratic.mesh.order == 1);
  REQUIRE(quadratic.mesh.num_nodes() == linear.mesh.num_nodes());
  CHECK((quadratic.mesh.x - linear.mesh.x).norm() < 1e-12);
  CHECK(quadratic.mesh.tri == linear.mesh.tri);
}
