#include "curving/rotate_boundary.h"

#include <array>
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.h"
#include "core/raise_order.h"
#include "quality/mesh_validity.h"

using namespace homesh;

namespace {

// Full annulus a <= r <= b about the origin: nt sectors by nr rings of cells,
// each cut along a diagonal, raised to order p; if `curved`, the nodes of the
// two circles are moved onto them.
struct Annulus {
  Mesh m;
  std::vector<bool> inner, outer, boundary;
};

Annulus annulus(int nt, int nr, double a, double b, int p, bool curved = true) {
  Mesh lin;
  lin.x.resize(2, nt * (nr + 1));
  for (int j = 0; j <= nr; ++j)
    for (int i = 0; i < nt; ++i) {
      const double r = a + (b - a) * j / nr, t = 2 * M_PI * i / nt;
      lin.x.col(j * nt + i) << r * std::cos(t), r * std::sin(t);
    }
  lin.node_class.resize(lin.x.cols());
  lin.tri.resize(3, 2 * nt * nr);
  for (int j = 0; j < nr; ++j)
    for (int i = 0; i < nt; ++i) {
      const int v00 = j * nt + i, v10 = j * nt + (i + 1) % nt, v01 = v00 + nt, v11 = v10 + nt;
      // (theta, r) -> (x, y) reverses orientation: list the corners clockwise in (theta, r).
      lin.tri.col(2 * (j * nt + i)) << v00, v11, v10;
      lin.tri.col(2 * (j * nt + i) + 1) << v00, v01, v11;
    }
  lin.tri_entity.assign(lin.tri.cols(), 1);
  Annulus s{raise_order(lin, p), {}, {}, {}};
  for (int i = 0; i < s.m.num_nodes(); ++i) {
    const double r = s.m.x.col(i).norm();
    // Edge nodes of a chord lie inside the circle by at most the sagitta.
    const bool in = r<a*(1 + 1e-12), out = r> b * std::cos(M_PI / nt) - 1e-12;
    if (curved && in) s.m.x.col(i) *= a / r;
    if (curved && out) s.m.x.col(i) *= b / r;
    s.inner.push_back(in);
    s.outer.push_back(out);
    s.boundary.push_back(in || out);
  }
  return s;
}

double wall_error(const RotateResult& r, const Mesh& m, const std::vector<bool>& wall) {
  const double t = r.theta_max * M_PI / 180;
  Eigen::Matrix2d R;
  R << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
  double e = 0;
  for (int i = 0; i < m.num_nodes(); ++i)
    if (wall[i]) e = std::max(e, (r.mesh.x.col(i) - R * m.x.col(i)).norm());
  return e;
}

}  // namespace

TEST_CASE("rotating the inner circle of an annulus: small angles valid, large ones not",
          "[curving][rotate]") {
  Annulus s = annulus(16, 3, 1, 2, 2);
  REQUIRE(mesh_validity(s.m).invalid == 0);
  for (int i = 0; i < s.m.num_nodes(); ++i)
    if (s.boundary[i]) s.m.node_class[i] = {1, s.inner[i] ? 1 : 2, 0.5};
  RotateOptions opt;
  opt.centre = Eigen::Vector2d::Zero();
  opt.max_angle = 6;
  opt.step = 2;
  RotateResult r = rotate_boundary(s.m, s.inner, s.boundary, opt);
  REQUIRE(r.reached_max);
  REQUIRE(r.theta_max == 6);
  REQUIRE(r.steps == 3);
  REQUIRE(r.solves == 3);
  REQUIRE(r.invalid_at_failure == 0);
  REQUIRE(wall_error(r, s.m, s.inner) < 1e-12);
  for (int i = 0; i < s.m.num_nodes(); ++i) {
    if (s.outer[i]) REQUIRE(r.mesh.x.col(i) == s.m.x.col(i));
    // A rotated wall node's curve parameter no longer matches its position.
    if (s.boundary[i]) REQUIRE(std::isnan(r.mesh.node_class[i].u) == s.inner[i]);
  }

  opt.max_angle = 360;
  opt.step = 5;
  r = rotate_boundary(s.m, s.inner, s.boundary, opt);
  CAPTURE(r.theta_max);
  REQUIRE_FALSE(r.reached_max);
  REQUIRE(r.theta_max >= 30);
  REQUIRE(r.theta_max < 180);
  REQUIRE(std::fmod(r.theta_max, 5.0) == 0);
  REQUIRE(r.solves == r.steps + 1);
  REQUIRE(r.invalid_at_failure > 0);
  const MeshValidity v = mesh_validity(r.mesh);
  REQUIRE(v.invalid == 0);
  REQUIRE(r.worst_ratio <= v.worst);
  REQUIRE(r.worst_ratio > 0);
  REQUIRE(wall_error(r, s.m, s.inner) < 1e-12);
}

TEST_CASE("clockwise rotation of the mirrored mesh is the anticlockwise one, mirrored",
          "[curving][rotate]") {
  const Annulus s = annulus(16, 3, 1, 2, 2);
  Annulus mirrored = s;
  mirrored.m.x.row(1) *= -1;
  // Reflection reverses orientation: swap corners 1, 2 and edge nodes 3, 5 (p = 2).
  const std::array<int, 6> flip{0, 2, 1, 5, 4, 3};
  for (int e = 0; e < s.m.num_triangles(); ++e)
    for (int k = 0; k < 6; ++k) mirrored.m.tri(k, e) = s.m.tri(flip[k], e);
  // The same up to quadrature (the rules are not symmetric under relabelling).
  RotateOptions opt;
  opt.centre = Eigen::Vector2d::Zero();
  opt.step = 5;
  const RotateResult ccw = rotate_boundary(s.m, s.inner, s.boundary, opt);
  opt.step = -5;
  const RotateResult cw = rotate_boundary(mirrored.m, s.inner, s.boundary, opt);
  REQUIRE_FALSE(ccw.reached_max);
  REQUIRE(std::abs(cw.theta_max - ccw.theta_max) <= 5);
  REQUIRE(cw.theta_max > 60);
  opt.max_angle = 60;
  Eigen::Matrix2Xd back = rotate_boundary(mirrored.m, s.inner, s.boundary, opt).mesh.x;
  back.row(1) *= -1;
  opt.step = 5;
  REQUIRE((back - rotate_boundary(s.m, s.inner, s.boundary, opt).mesh.x).cwiseAbs().maxCoeff() <
          1e-4);
}

TEST_CASE("a wall covering the whole boundary turns the mesh rigidly, any angle",
          "[curving][rotate]") {
  // Straight-sided, so every added term vanishes (min Q / max Q = 1, metric
  // unchanged by a rotation) and E is uniform: the
  // linear field (R - I) x, whose small strain (cos t - 1) I is constant, is
  // then in equilibrium, and each solve reproduces the rotation exactly. (The
  // area formulations, E = 1/Ae and T = 1/Ae, vary from ring to ring.)
  const Annulus s = annulus(12, 2, 1, 2, 3, false);
  const double worst = mesh_validity(s.m).worst;
  for (const auto& f : analogy_formulations()) {
    if (f.name == "area" || f.name == "heat_area") continue;
    for (bool total : {false, true}) {
      CAPTURE(f.name, total);
      RotateOptions opt;
      opt.centre = Eigen::Vector2d::Zero();
      opt.total = total;
      opt.step = 45;
      opt.max_angle = 360;
      opt.formulation = f.name;
      const RotateResult r = rotate_boundary(s.m, s.boundary, s.boundary, opt);
      REQUIRE(r.reached_max);
      REQUIRE(r.theta_max == 360);
      REQUIRE(r.solves == 8);
      REQUIRE((r.mesh.x - s.m.x).cwiseAbs().maxCoeff() < 1e-9);
      REQUIRE(r.worst_ratio == Approx(worst).margin(1e-9));
    }
  }
}

TEST_CASE("theta_max grows with the room the annulus gives the rotation", "[curving][rotate]") {
  // Same mesh topology, outer radius b: the twist per unit of radial distance
  // falls as b grows (in the linear solution the hoop displacement is
  // A r + B / r), so the first inverted element comes later.
  RotateOptions opt;
  opt.centre = Eigen::Vector2d::Zero();
  opt.step = 2;
  double previous = 0;
  for (double b : {1.3, 1.6, 2.2}) {
    CAPTURE(b);
    const Annulus s = annulus(16, 3, 1, b, 2);
    const RotateResult r = rotate_boundary(s.m, s.inner, s.boundary, opt);
    CAPTURE(r.theta_max);
    REQUIRE_FALSE(r.reached_max);
    REQUIRE(r.theta_max > previous);
    previous = r.theta_max;
  }
}

TEST_CASE("fitted circle centre: exact on a circle, refused on a line", "[curving][rotate]") {
  Eigen::Matrix2Xd p(2, 5);
  const double t[] = {0.1, 0.3, 2.0, 2.2, 4.0};
  for (int k = 0; k < 5; ++k) p.col(k) << 3 + 0.7 * std::cos(t[k]), -2 + 0.7 * std::sin(t[k]);
  REQUIRE((fitted_circle_centre(p) - Eigen::Vector2d(3, -2)).norm() < 1e-12);
  Eigen::Matrix2Xd line(2, 4);
  line << 0, 1, 2, 3, 1, 2, 3, 4;
  REQUIRE_THROWS_AS(fitted_circle_centre(line), Error);
  REQUIRE_THROWS_AS(fitted_circle_centre(p.leftCols(2)), Error);
}

TEST_CASE("rotate_boundary refuses bad arguments", "[curving][rotate]") {
  const Annulus s = annulus(8, 1, 1, 2, 2);
  const std::vector<bool> none(s.m.num_nodes(), false), all(s.m.num_nodes(), true);
  REQUIRE_THROWS_AS(rotate_boundary(s.m, none, s.boundary), Error);
  REQUIRE_THROWS_AS(rotate_boundary(s.m, all, s.boundary), Error);  // interior in the wall
  REQUIRE_THROWS_AS(rotate_boundary(s.m, s.inner, none), Error);
  REQUIRE_THROWS_AS(rotate_boundary(s.m, s.inner, {true}), Error);
  RotateOptions opt;
  opt.centre = Eigen::Vector2d::Zero();
  opt.step = 0;
  REQUIRE_THROWS_AS(rotate_boundary(s.m, s.inner, s.boundary, opt), Error);
  opt.step = 1;
  opt.substeps = 0;
  REQUIRE_THROWS_AS(rotate_boundary(s.m, s.inner, s.boundary, opt), Error);
  opt.substeps = 1;
  opt.formulation = "nosuch";
  REQUIRE_THROWS_WITH(rotate_boundary(s.m, s.inner, s.boundary, opt),
                      Catch::Contains("unknown formulation 'nosuch'"));
}
