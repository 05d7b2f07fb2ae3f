#include "curving/deform_mesh.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "../fem/fem_test_support.h"
#include "core/error.h"
#include "quality/mesh_validity.h"

using namespace homesh;

namespace {

// The thesis' analogy (E = 1, nu = 0.4) in 4 increments on the whole mesh: the
// setting these tests were written for, given explicitly since DeformOptions'
// defaults became the curve stage's.
DeformOptions thesis_options() {
  DeformOptions o;
  o.formulation = "plain";
  o.params.poisson = 0.4;
  o.increments = 4;
  o.reach = 0;
  return o;
}

void classify_square_boundary(Mesh& m) {
  for (int i : fem_test::square_boundary(m)) m.node_class[i] = {1, 1};
}

// Straight-sided quarter annulus 1 <= r <= 2 (corners on the circles), with
// targets that put every boundary node of the order-p mesh on the circles. The
// radial divisions are graded as r = 1 + u^grading (grading > 1: thin layers on
// the inner circle).
struct Annulus {
  Mesh m;
  Eigen::Matrix2Xd target;
  std::vector<bool> prescribed;
};

Annulus straight_annulus(int n, int p, double grading = 1) {
  const Mesh param = fem_test::unit_square(n, 1);
  Mesh lin = param;
  for (int i = 0; i < lin.num_nodes(); ++i) {
    const double r = 1 + std::pow(param.x(0, i), grading), t = M_PI / 2 * param.x(1, i);
    lin.x.col(i) << r * std::cos(t), r * std::sin(t);
  }
  // raise_order numbers new nodes by connectivity alone, so node i of both
  // raised meshes is the same node: classify by its parameter coordinates.
  const Mesh s = raise_order(param, p);
  Annulus a{raise_order(lin, p), {}, {}};
  a.target = a.m.x;
  a.prescribed.assign(a.m.num_nodes(), false);
  for (int i = 0; i < a.m.num_nodes(); ++i) {
    const double u = s.x(0, i), v = s.x(1, i);
    a.prescribed[i] = std::min({u, v, 1 - u, 1 - v}) < 1e-12;
    if (std::abs(u) < 1e-12 || std::abs(u - 1) < 1e-12) {
      const Eigen::Vector2d x = a.m.x.col(i);
      a.target.col(i) = (1 + u) * x.normalized();  // u^grading = u at u = 0, 1
    }
  }
  return a;
}

}  // namespace

TEST_CASE("a rigid rotation of the boundary rotates the interior exactly", "[curving]") {
  for (int p : {1, 3}) {
    Mesh m = fem_test::unit_square(4, p);
    classify_square_boundary(m);
    const double angle = 0.5;
    Eigen::Matrix2d R;
    R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    const Eigen::Vector2d c(0.5, 0.5);
    const Eigen::Matrix2Xd target = (R * (m.x.colwise() - c)).colwise() + c;
    DeformOptions opt = thesis_options();
    opt.increments = 3;
    const DeformResult r = deform_mesh(m, target, boundary_nodes(m), opt);
    REQUIRE(r.complete);
    REQUIRE(r.reached == 1.0);
    REQUIRE(r.solves == 3);
    // Each increment is a linear field on the current mesh: reproduced exactly.
    REQUIRE((r.mesh.x - target).cwiseAbs().maxCoeff() < 1e-10);
    REQUIRE(r.worst_ratio == Approx(1.0).margin(1e-9));
  }
}

TEST_CASE("every formulation curves a quarter annulus onto its circles, valid", "[curving]") {
  Annulus a = straight_annulus(4, 4);
  for (const auto& f : analogy_formulations()) {
    CAPTURE(f.name);
    DeformOptions opt = thesis_options();
    opt.formulation = f.name;
    opt.increments = 2;
    const DeformResult r = deform_mesh(a.m, a.target, a.prescribed, opt);
    REQUIRE(r.complete);
    REQUIRE(mesh_validity(r.mesh).invalid == 0);
    double off_circle = 0;
    for (int i = 0; i < a.m.num_nodes(); ++i)
      if (a.prescribed[i])
        off_circle = std::max(off_circle, (r.mesh.x.col(i) - a.target.col(i)).norm());
    REQUIRE(off_circle < 1e-12);
    REQUIRE(r.worst_ratio > 0.5);
  }
}

TEST_CASE("on a straight mesh the heat terms vanish: same result as plain", "[curving]") {
  Annulus a = straight_annulus(3, 2);
  DeformOptions opt = thesis_options();
  opt.increments = 1;
  const Mesh plain = deform_mesh(a.m, a.target, a.prescribed, opt).mesh;
  // Every added term is zero on the mesh the deformation starts from.
  for (const char* name :
       {"heat_q17", "heat_q4", "force_q17", "stiff_q17", "metric_ideal", "metric_ref"}) {
    CAPTURE(name);
    opt.formulation = name;
    const Mesh other = deform_mesh(a.m, a.target, a.prescribed, opt).mesh;
    REQUIRE((other.x - plain.x).cwiseAbs().maxCoeff() < 1e-10);
  }
  // With two increments the second sees the distortion the first made.
  opt.increments = 2;
  opt.formulation = "plain";
  const Mesh plain2 = deform_mesh(a.m, a.target, a.prescribed, opt).mesh;
  for (const char* name : {"heat_q17", "metric_ideal"}) {
    CAPTURE(name);
    opt.formulation = name;
    const Mesh other = deform_mesh(a.m, a.target, a.prescribed, opt).mesh;
    REQUIRE((other.x - plain2.x).cwiseAbs().maxCoeff() > 1e-6);
  }
}

TEST_CASE("an impossible deformation stops at the last valid state", "[curving]") {
  Mesh m = fem_test::unit_square(4, 2);
  classify_square_boundary(m);
  Eigen::Matrix2Xd target = m.x;
  int moved = -1;
  for (int i = 0; i < m.num_nodes(); ++i)
    if (std::abs(m.x(0, i)) < 1e-12 && std::abs(m.x(1, i) - 0.5) < 1e-12) moved = i;
  REQUIRE(moved >= 0);
  target(0, moved) = 1.5;  // drag a left-side node out through the right side
  DeformOptions opt = thesis_options();
  opt.max_halvings = 4;
  const DeformResult r = deform_mesh(m, target, boundary_nodes(m), opt);
  REQUIRE_FALSE(r.complete);
  REQUIRE(r.reached < 1.0);
  REQUIRE(r.invalid_at_failure > 0);
  REQUIRE(mesh_validity(r.mesh).invalid == 0);
  opt.formulation = "nosuch";
  REQUIRE_THROWS_AS(deform_mesh(m, target, boundary_nodes(m), opt), Error);
}

TEST_CASE("layers = k solves near the moving nodes only; enough layers give the full solve",
          "[curving]") {
  const Annulus a = straight_annulus(6, 3);
  DeformOptions opt = thesis_options();
  const DeformResult full = deform_mesh(a.m, a.target, a.prescribed, opt);
  std::vector<bool> moving(a.m.num_nodes());
  for (int i = 0; i < a.m.num_nodes(); ++i)
    moving[i] = a.prescribed[i] && a.target.col(i) != a.m.x.col(i);
  // Only the edge nodes of the 6 + 6 straight chords of the circles move (their
  // ends are on the circles): layer 1 is the one triangle on each chord.
  const std::vector<int> one = moving_region(a.m, moving, 1);
  CHECK(one.size() == 2 * 6);
  CHECK(moving_region(a.m, moving, 3).size() < std::size_t(a.m.num_triangles()));
  CHECK(moving_region(a.m, moving, 6).size() == std::size_t(a.m.num_triangles()));

  opt.layers = 1;
  const DeformResult near = deform_mesh(a.m, a.target, a.prescribed, opt);
  REQUIRE(near.complete);
  REQUIRE(mesh_validity(near.mesh).invalid == 0);
  CHECK(near.worst_ratio == Approx(mesh_validity(near.mesh).worst));
  std::vector<bool> in_region(a.m.num_nodes(), false);
  for (int e : one)
    for (int i = 0; i < a.m.tri.rows(); ++i) in_region[a.m.tri(i, e)] = true;
  double off_target = 0, moved_outside = 0;
  for (int i = 0; i < a.m.num_nodes(); ++i) {
    const double d = (near.mesh.x.col(i) - a.m.x.col(i)).norm();
    if (a.prescribed[i])
      off_target = std::max(off_target, (near.mesh.x.col(i) - a.target.col(i)).norm());
    if (!in_region[i]) moved_outside = std::max(moved_outside, d);
  }
  CHECK(off_target < 1e-12);
  CHECK(moved_outside == 0.0);
  CHECK((near.mesh.x - full.mesh.x).cwiseAbs().maxCoeff() > 1e-6);

  opt.layers = 6;
  const DeformResult all = deform_mesh(a.m, a.target, a.prescribed, opt);
  CHECK((all.mesh.x - full.mesh.x).cwiseAbs().maxCoeff() < 1e-12);
  CHECK(all.worst_ratio == Approx(full.worst_ratio).epsilon(1e-12));
}

TEST_CASE("reach = r solves within r wall-triangle sizes of the moving wall, through thin layers",
          "[curving]") {
  // 12 radial divisions graded r = 1 + u^4: the first layer on the inner circle is
  // 5e-5 thick, its wall chords 0.13 long.
  Annulus a = straight_annulus(12, 2, 4);
  for (int i = 0; i < a.m.num_nodes(); ++i)  // only the inner circle's chords move
    if (a.m.x.col(i).norm() > 1.5) a.target.col(i) = a.m.x.col(i);
  std::vector<bool> moving(a.m.num_nodes());
  for (int i = 0; i < a.m.num_nodes(); ++i)
    moving[i] = a.prescribed[i] && a.target.col(i) != a.m.x.col(i);
  // Exactly the triangles with a corner within 2 h_t of a wall triangle's centroid.
  std::vector<std::pair<Eigen::Vector2d, double>> disks;
  for (int e = 0; e < a.m.num_triangles(); ++e) {
    bool touches = false;
    for (int i = 0; i < a.m.tri.rows(); ++i) touches = touches || moving[a.m.tri(i, e)];
    if (!touches) continue;
    double h = 0;
    for (int k = 0; k < 3; ++k)
      h = std::max(h, (a.m.x.col(a.m.tri(k, e)) - a.m.x.col(a.m.tri((k + 1) % 3, e))).norm());
    disks.push_back({a.m.corner_centroid(e), 2 * h});
  }
  std::vector<int> expected;
  for (int e = 0; e < a.m.num_triangles(); ++e) {
    bool in = false;
    for (int k = 0; k < 3 && !in; ++k)
      for (const auto& [c, r] : disks) in = in || (a.m.x.col(a.m.tri(k, e)) - c).norm() <= r;
    if (in) expected.push_back(e);
  }
  const std::vector<int> region = reach_region(a.m, moving, 2);
  CHECK(region == expected);
  CHECK(region.size() < std::size_t(a.m.num_triangles()));
  // Two element layers stop within 0.001 of the inner circle; the reach region goes
  // through all the thin layers there to r > 1.2.
  double layers_out = 0, reach_out = 0;
  for (int e : moving_region(a.m, moving, 2))
    for (int k = 0; k < 3; ++k) layers_out = std::max(layers_out, a.m.x.col(a.m.tri(k, e)).norm());
  for (int e : region)
    for (int k = 0; k < 3; ++k) reach_out = std::max(reach_out, a.m.x.col(a.m.tri(k, e)).norm());
  CHECK(layers_out < 1.01);
  CHECK(reach_out > 1.2);
  // The same region with the mesh in the third quadrant (negative grid cells).
  Mesh turned = a.m;
  turned.x = -a.m.x;
  CHECK(reach_region(turned, moving, 2) == region);

  DeformOptions opt = thesis_options();
  opt.formulation = "area";
  opt.params.poisson = 0.49;
  const DeformResult full = deform_mesh(a.m, a.target, a.prescribed, opt);
  opt.reach = 2;
  const DeformResult reach = deform_mesh(a.m, a.target, a.prescribed, opt);
  CHECK(reach.solved_triangles == int(region.size()));
  REQUIRE(full.complete);
  REQUIRE(reach.complete);
  REQUIRE(mesh_validity(reach.mesh).invalid == 0);
  // Held still beyond 2 wall chords, the layers keep the quality of the whole-mesh
  // solve within 0.01 (0.980 against 0.984); held beyond 2 element layers, the
  // thin layers all but fold (worst 4e-7).
  INFO("worst minJ/maxJ: whole mesh " << full.worst_ratio << ", reach 2 " << reach.worst_ratio);
  CHECK(reach.worst_ratio > full.worst_ratio - 0.01);
  opt.reach = 0;
  opt.layers = 2;
  const DeformResult layers = deform_mesh(a.m, a.target, a.prescribed, opt);
  INFO("layers 2 " << layers.worst_ratio);
  CHECK(layers.worst_ratio < 0.1);
  // layers > 0 replaces reach.
  opt.reach = 2;
  const DeformResult both = deform_mesh(a.m, a.target, a.prescribed, opt);
  CHECK(both.solved_triangles == layers.solved_triangles);
  CHECK((both.mesh.x - layers.mesh.x).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("an explicit region: its prescribed nodes solved, those outside it put on target",
          "[curving]") {
  // The annulus's chords curved, the solve only on the first of the 12 chord triangles
  // (layer 1): the other 11 chords' edge nodes still reach the circles.
  const Annulus a = straight_annulus(6, 3);
  std::vector<bool> moving(a.m.num_nodes());
  for (int i = 0; i < a.m.num_nodes(); ++i)
    moving[i] = a.prescribed[i] && a.target.col(i) != a.m.x.col(i);
  const std::vector<int> one = moving_region(a.m, moving, 1);
  REQUIRE(one.size() == 12);
  DeformOptions opt = thesis_options();
  opt.region = {one[0]};
  const DeformResult r = deform_mesh(a.m, a.target, a.prescribed, opt);
  REQUIRE(r.complete);
  CHECK(r.solved_triangles == 1);
  double off_target = 0;
  int moved = 0;
  for (int i = 0; i < a.m.num_nodes(); ++i)
    if (a.prescribed[i]) {
      off_target = std::max(off_target, (r.mesh.x.col(i) - a.target.col(i)).norm());
      moved += moving[i];
    }
  CHECK(moved == 2 * 12);  // the two edge nodes of each of the 12 chords
  CHECK(off_target < 1e-12);
  CHECK(r.worst_ratio == Approx(mesh_validity(r.mesh).worst));
}
