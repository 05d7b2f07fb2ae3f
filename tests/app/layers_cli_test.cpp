// The layers stage run as a user does (thesis Section 4.3, Figs 4.8-4.12):
// boundary layers opened by the elastic analogy, then curved, certified valid.
#include <gmsh.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "../support/gmsh_session.h"
#include "../support/run_command.h"
#include "../support/temp_dir.h"
#include "gmsh/read_model.h"

using homesh::test::run_homesh;
using homesh::test::TempDir;

namespace {

using homesh::test::geo;

struct LayerLog {
  int wall_edges = 0, fans = 0, before = 0, after = 0, corner_triangles = 0;
  int cleared = 0;  ///< free nodes removed from the room, 2 triangles each
  double corner_q = 0;
};

// The numbers of the layers stage's log.
LayerLog parse(const std::string& out) {
  LayerLog l;
  std::smatch m;
  REQUIRE(std::regex_search(out, m, std::regex(R"((\d+) wall edges, (\d+) fans)")));
  l.wall_edges = std::stoi(m[1]);
  l.fans = std::stoi(m[2]);
  REQUIRE(std::regex_search(out, m, std::regex(R"((\d+) free node\(s\) in the room removed)")));
  l.cleared = std::stoi(m[1]);
  REQUIRE(std::regex_search(out, m, std::regex(R"((\d+) -> (\d+) triangles)")));
  l.before = std::stoi(m[1]);
  l.after = std::stoi(m[2]);
  REQUIRE(
      std::regex_search(out, m, std::regex(R"(min Q (\d\.\d+) over its (\d+) layer elements)")));
  l.corner_q = std::stod(m[1]);
  l.corner_triangles = std::stoi(m[2]);
  return l;
}

}  // namespace

TEST_CASE("layers: 3 layers around the plate's hole, curved at p = 3, valid (Fig 4.8)", "[app]") {
  const TempDir dir;
  const std::string out = dir / "plate.msh";
  const auto r = run_homesh(geo +
                            "plate_hole.geo -m mesh -m layers:walls=hole:n=3:first=0.01:"
                            "ratio=1.3 -m curve:p=3 -m quality " +
                            out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.output.find("validity: 0 invalid of") != std::string::npos);
  const LayerLog l = parse(r.output);
  CHECK(l.fans == 0);
  CHECK(l.after == l.before - 2 * l.cleared + 2 * 3 * l.wall_edges);
  // The hole keeps its nodes on the circle; the first layer's corners stand 0.01 off it
  // (times the miter 1 / sin(theta / 2), theta about 191 deg; the curving moves them a little).
  homesh::test::GmshSession session;
  gmsh::open(out);
  const homesh::Mesh m = homesh::gmsh_adapter::read_model(out);
  REQUIRE(m.order == 3);
  double off = 0, first = 1;
  for (int k = 0; k < m.num_lines(); ++k)
    for (int j = 0; j <= 3; ++j) {
      const double rad = m.x.col(m.line(j, k)).norm();
      if (rad < 0.75) off = std::max(off, std::abs(rad - 0.5));
    }
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int j = 0; j < 3; ++j) {
      const int i = m.tri(j, e);
      if (m.node_class[i].dim == 2) first = std::min(first, m.x.col(i).norm() - 0.5);
    }
  CHECK(off < 1e-12);
  CHECK(first > 0.01 - 1e-12);
  CHECK(first < 0.0105);
}

TEST_CASE("layers: 15 layers on NACA-7526 with single normals, curved at p = 3 (Fig 4.9)",
          "[app]") {
  const TempDir dir;
  const std::string out = dir / "naca15.msh";
  const auto r = run_homesh(geo +
                            "naca.geo -m mesh -m layers:walls=aerofoil:n=15:first=1e-3:"
                            "ratio=1.2 -m curve:p=3 -m quality " +
                            out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.output.find("thickness 0.0720351") != std::string::npos);
  REQUIRE(r.output.find("validity: 0 invalid of") != std::string::npos);
  const LayerLog l = parse(r.output);
  CHECK(l.after == l.before - 2 * l.cleared + 2 * 15 * l.wall_edges);
  CHECK(l.corner_triangles == 4 * 15);  // the two wall-edge strips at the trailing edge
}

TEST_CASE("layers: 5 normals at the trailing edge beat a single one (Figs 4.10, 4.12)", "[app]") {
  const TempDir dir;
  const std::string out = dir / "naca4.msh";
  const std::string layers = "naca.geo -m mesh -m layers:walls=aerofoil:n=4:first=1e-3:ratio=1.2";
  auto r = run_homesh(geo + layers + " " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const LayerLog single = parse(r.output);
  // The trailing edge's domain angle is 326 deg: below the default fan_angle, as the log warns.
  r = run_homesh(geo + layers + ":normals=multi " + out);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.output.find("no wall node reaches fan_angle = 330 deg") != std::string::npos);
  r = run_homesh(geo + layers + ":normals=multi:fan=5:fan_angle=320 -m curve:p=3 -m quality " +
                 out);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.output.find("validity: 0 invalid of") != std::string::npos);
  const LayerLog multi = parse(r.output);
  CHECK(multi.fans == 1);
  CHECK(multi.after + 2 * multi.cleared == single.after + 2 * single.cleared + 2 * 4 * (5 - 1));
  CHECK(multi.corner_triangles == 4 * 4 + (5 - 1) * (2 * 4 - 1));
  CHECK(single.corner_q < 0.1);
  CHECK(multi.corner_q > 0.3);
}

TEST_CASE("layers: the README's NACA-7526 stack on a mesh twice as fine opens in few steps",
          "[app]") {
  // Factor 0.5: 29 trailing-edge elements under the 0.072 stack. Pushing them all
  // ahead of the front stalled after 200 steps; the room is cleared of them instead.
  const auto r = run_homesh(geo +
                            "naca.geo -m mesh:factor=0.5 -m layers:walls=aerofoil:n=15:"
                            "first=1e-3:ratio=1.2:normals=multi:fan=5:fan_angle=320");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const LayerLog l = parse(r.output);
  CHECK(l.fans == 1);
  CHECK(l.cleared > 1000);  // measured 1737 of 4968 nodes
  CHECK(l.after == l.before - 2 * l.cleared + 2 * 15 * l.wall_edges + 2 * 15 * 4);
  std::smatch m;
  REQUIRE(std::regex_search(r.output, m, std::regex(R"(room opened in (\d+) elastic step)")));
  CHECK(std::stoi(m[1]) < 20);  // measured 4
  REQUIRE(std::regex_search(r.output, m, std::regex(R"(of the other triangles: min (\d\.\d+))")));
  CHECK(std::stod(m[1]) > 0.2);  // measured 0.25
  CHECK(r.output.find("thinned") == std::string::npos);
}

TEST_CASE("layers: 5 layers on a channel's floor end along inlet and outlet, p = 3, valid",
          "[app]") {
  const TempDir dir;
  const std::string out = dir / "channel.msh";
  const auto r = run_homesh(geo +
                            "channel.geo -m mesh -m layers:walls=wall:n=5:first=1e-3:"
                            "ratio=1.3 -m curve:p=3 -m quality " +
                            out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.output.find("validity: 0 invalid of") != std::string::npos);
  REQUIRE(r.output.find("1 of the walls open") != std::string::npos);
  const LayerLog l = parse(r.output);
  CHECK(l.after == l.before - 2 * l.cleared + 2 * 5 * l.wall_edges);
  std::smatch q;
  REQUIRE(std::regex_search(r.output, q, std::regex(R"(validity: .* worst minJ/maxJ (\d\.\d+))")));
  // Measured 0.9809: the wall's bulge moved into the layers (curve's propagate, 0.925),
  // then solved round its elements below 0.98 (polish; the solve within reach: 0.9968).
  CHECK(std::stod(q[1]) > 0.98);

  // The inlet (curve 6) is split at the layer nodes: its corners below the thickness
  // d_5 = 0.0090431 are the floor's end, the 4 layer nodes and the front node, at the
  // depths d_k = 1e-3 (1.3^k - 1) / 0.3, all on x = 0.
  homesh::test::GmshSession session;
  gmsh::open(out);
  const homesh::Mesh m = homesh::gmsh_adapter::read_model(out);
  REQUIRE(m.order == 3);
  std::set<int> corners;
  double off = 0;
  for (int k = 0; k < m.num_lines(); ++k) {
    if (m.line_entity[k] != 6) continue;
    for (int j = 0; j <= 3; ++j) off = std::max(off, std::abs(m.x(0, m.line(j, k))));
    corners.insert({m.line(0, k), m.line(1, k)});
  }
  std::vector<double> low;
  for (int i : corners)
    if (m.x(1, i) < 0.0091) low.push_back(m.x(1, i));
  std::sort(low.begin(), low.end());
  REQUIRE(low.size() == 6);
  for (int k = 0; k <= 5; ++k)
    CHECK(low[k] == Approx(1e-3 * (std::pow(1.3, k) - 1) / 0.3).margin(1e-12));
  CHECK(off < 1e-12);
}

TEST_CASE("layers: refusals name the cause", "[app]") {
  const TempDir dir;
  const std::string out = dir / "refused.msh";
  // The hole (radius 0.5) is 0.5 from the box: room for 0.4 * 0.5 = 0.2 (0.199 along
  // the miter of the 32-gon's normals), less than a first layer of 0.3; the stack 1.319 deep of
  // first = 0.1 is thinned.
  auto r = run_homesh(geo + "plate_hole.geo -m mesh -m layers:walls=hole:n=5:first=0.3:ratio=1.5 " +
                      out);
  CHECK(r.exit_code != 0);
  CHECK(r.output.find("no layer fits at the wall node") != std::string::npos);
  CHECK(r.output.find("first = 0.099 would fit") != std::string::npos);
  r = run_homesh(geo + "plate_hole.geo -m mesh -m layers:walls=hole:n=5:first=0.1:ratio=1.5 " +
                 out);
  CHECK(r.exit_code == 0);
  CHECK(r.output.find("stack thinned to 15 % (0.199 of 1.319)") != std::string::npos);
  r = run_homesh(geo + "plate_hole.geo -m mesh -m layers:walls=wing " + out);
  CHECK(r.exit_code != 0);
  CHECK(r.output.find("no wall 'wing': not a curve physical group (hole, farfield)") !=
        std::string::npos);
  r = run_homesh(geo + "plate_hole.geo -m mesh -m layers:walls=hole:normals=many " + out);
  CHECK(r.exit_code != 0);
  CHECK(r.output.find("normals=many: expected single or multi") != std::string::npos);
}

namespace {

// theta_max (degrees, clockwise) of the coarse quadratic NACA-7526 boundary-layer mesh of
// scripts/naca_rotation.py (thesis Section 4.4.2) turned about its quarter chord, nu = 0.25.
int naca_theta_max(const std::string& fan, const std::string& formulation) {
  const TempDir dir;
  const auto r = run_homesh(geo +
                            "naca7526_rotation.geo -m mesh -m layers:walls=aerofoil:n=2:"
                            "first=0.02:ratio=1.2" +
                            fan +
                            " -m curve:p=2:rings=0 -m rotate:wall=aerofoil:"
                            "centre=0.25,0:step=-1:max=90:nu=0.25:" +
                            formulation + " " + dir / "naca_rotation.msh");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  std::smatch m;
  REQUIRE(std::regex_search(r.output, m, std::regex(R"(rotate: theta_max = (\d+) deg)")));
  return std::stoi(m[1]);
}

}  // namespace

TEST_CASE("layers: NACA-7526 rotation - 5 normals at the trailing edge turn further (Sec 4.4.2)",
          "[app]") {
  // The first element to fold is at the trailing edge, where the fan of 5 normals leaves
  // better-shaped elements: the thesis' 62 vs 22 degrees (T = 1/Ae) and 125 vs 85 (metric).
  // Measured: plain analogy 8 (single) and 17 (fan); T = 1/Ae at heat 0.01: 24 (single).
  const int single = naca_theta_max("", "formulation=plain");
  const int fan = naca_theta_max(":normals=multi:fan=5:fan_angle=320", "formulation=plain");
  CHECK(single >= 5);
  CHECK(fan >= single + 5);
  // T = 1/Ae (thesis case 1) heats the small layer and trailing-edge elements: it turns
  // the single-normal mesh much further than the plain analogy.
  const int area = naca_theta_max("", "formulation=heat_area:heat=0.01");
  CHECK(area >= 2 * single);
}

TEST_CASE("layers: cells=quads keeps each wall edge's layer cells quadrilaterals, curved valid",
          "[app][quads]") {
  // NACA-7526, 15 layers with a fan of 5 normals at the trailing edge: each wall edge's n
  // cells are quadrilaterals, whose two triangles they replace; the fan stays triangles.
  const std::string base =
      geo +
      "naca.geo -m mesh "
      "-m layers:walls=aerofoil:n=15:first=1e-3:ratio=1.2:normals=multi:fan=5:fan_angle=320";
  const auto tris = run_homesh(base);
  REQUIRE(tris.exit_code == 0);
  const TempDir dir;
  const std::string out = dir / "naca_quads.msh";
  const auto r = run_homesh(base + ":cells=quads -m curve:p=3 " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  std::smatch m;
  REQUIRE(std::regex_search(
      r.output, m,
      std::regex(R"((\d+) -> (\d+) triangles and (\d+) quadrilaterals, \d+ -> (\d+))")));
  const int triangles = std::stoi(m[2]), quads = std::stoi(m[3]);
  const LayerLog l = parse(tris.output);
  CHECK(quads == 15 * l.wall_edges);        // 1815
  CHECK(triangles + 2 * quads == l.after);  // 1909 + 2 x 1815 = 5539
  REQUIRE(std::regex_search(tris.output, m, std::regex(R"(, \d+ -> (\d+) nodes)")));
  CHECK(r.output.find(" -> " + std::string(m[1]) + " nodes") != std::string::npos);  // 2856
  // Curved valid, as good as the triangle layers (tests above: 0.98 at p = 4).
  REQUIRE(std::regex_search(r.output, m,
                            std::regex(R"(validity: 0 invalid of \d+ triangles and (\d+) )"
                                       R"(quadrilaterals.*worst minJ/maxJ (\d\.\d+))")));
  CHECK(std::stoi(m[1]) == quads);
  CHECK(std::stod(m[2]) > 0.9);
  homesh::test::GmshSession session;
  gmsh::open(out);
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 2);
  CHECK(std::set<int>(types.begin(), types.end()) == std::set<int>{21, 36});  // P3 tri, P3 quad
}
