// deform_mesh and its regions on meshes of triangles and quadrilaterals: 2D
// elements indexed triangles first, then quadrilaterals (core/mesh.h).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "../fem/fem_test_support.h"
#include "curving/deform_mesh.h"
#include "quality/mesh_validity.h"

using namespace homesh;

namespace {

// The unit square in 6 by 6 cells of order 3: quadrilaterals in x < 1/2 (18,
// 2D elements 36..53), triangles elsewhere (36, elements 0..35). Targets: the
// bottom nodes with x < x_max pushed up to y = a sin(pi x) (a = 0.25 is above
// the first row's height 1/6, so moving them alone inverts it); every
// boundary node prescribed.
struct Bump {
  Mesh m;
  Eigen::Matrix2Xd target;
  std::vector<bool> prescribed, moving;
};

Bump bump(double a, double x_max) {
  Bump b{fem_test::mixed_square(6, 3, 3), {}, {}, {}};
  b.target = b.m.x;
  b.prescribed = boundary_nodes(b.m);
  b.moving.assign(b.m.num_nodes(), false);
  for (int i = 0; i < b.m.num_nodes(); ++i)
    if (b.m.x(1, i) < 1e-12 && b.m.x(0, i) < x_max) {
      b.target(1, i) = a * std::sin(M_PI * b.m.x(0, i));
      b.moving[i] = b.target.col(i) != b.m.x.col(i);
    }
  return b;
}

}  // namespace

TEST_CASE("deform_mesh on a mixed mesh: the bump is absorbed, every formulation certified valid",
          "[curving][quad]") {
  const Bump b = bump(0.25, 2.0);
  REQUIRE(b.m.num_triangles() == 36);
  REQUIRE(b.m.num_quads() == 18);
  Mesh placed = b.m;
  for (int i = 0; i < b.m.num_nodes(); ++i)
    if (b.prescribed[i]) placed.x.col(i) = b.target.col(i);
  REQUIRE(mesh_validity(placed).invalid > 0);  // the boundary alone inverts the first row

  // The defaults (the curve stage's: area, nu = 0.49, reach 2, one increment).
  const DeformResult r = deform_mesh(b.m, b.target, b.prescribed);
  CHECK(r.complete);
  CHECK(r.worst_ratio > 0.5);
  CHECK(r.worst_ratio == Approx(mesh_validity(r.mesh).worst));
  // reach 2: within two cell sizes of the bottom row, quadrilaterals included.
  CHECK(r.solved_triangles > 18);
  CHECK(r.solved_triangles < b.m.num_elements_2d());
  double off_target = 0;
  for (int i = 0; i < b.m.num_nodes(); ++i)
    if (b.prescribed[i])
      off_target = std::max(off_target, (r.mesh.x.col(i) - b.target.col(i)).norm());
  CHECK(off_target < 1e-12);
  // The interior of the quads and of the triangles followed: a quad's own
  // interior node and the triangles' lowest interior vertex moved up.
  const int quad_interior = b.m.quad(12, 0);  // quadrilateral 0, cell (0, 0)
  CHECK(r.mesh.x(1, quad_interior) - b.m.x(1, quad_interior) > 0.02);
  int vertex = -1;
  for (int i = 0; i < b.m.num_nodes(); ++i)
    if (std::abs(b.m.x(0, i) - 4.0 / 6) < 1e-12 && std::abs(b.m.x(1, i) - 1.0 / 6) < 1e-12)
      vertex = i;
  REQUIRE(vertex >= 0);
  CHECK(r.mesh.x(1, vertex) - b.m.x(1, vertex) > 0.05);

  // Every formulation, whole mesh, two increments (metric_ref and
  // metric_ideal reach only 0.13 and 0.27 on this bump on triangles alone too).
  for (const AnalogyFormulation& f : analogy_formulations()) {
    INFO(f.name);
    DeformOptions o;
    o.formulation = f.name;
    o.params.poisson = 0.4;
    o.increments = 2;
    o.reach = 0;
    const DeformResult s = deform_mesh(b.m, b.target, b.prescribed, o);
    CHECK(s.complete);
    CHECK(s.worst_ratio > (f.name.rfind("metric", 0) == 0 ? 0.1 : 0.6));
    CHECK(s.solved_triangles == b.m.num_elements_2d());
  }
  // E = 1 / A_e with a quadrilateral's A_e half its area is uniform on this
  // grid of equal cells: in one increment (posed on the initial mesh) the
  // same motion as E = 1.
  DeformOptions o;
  o.reach = 0;
  o.formulation = "plain";
  const Eigen::Matrix2Xd plain = deform_mesh(b.m, b.target, b.prescribed, o).mesh.x;
  o.formulation = "area";
  const Eigen::Matrix2Xd area = deform_mesh(b.m, b.target, b.prescribed, o).mesh.x;
  CHECK((plain - area).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("regions on a mixed mesh index quadrilaterals after the triangles", "[curving][quad]") {
  // Moving nodes on the bottom of cells (0, 0) and (1, 0): quadrilaterals 0
  // and 1, 2D elements 36 and 37.
  const Bump b = bump(0.05, 0.3);
  const int T = b.m.num_triangles();
  CHECK(moving_region(b.m, b.moving, 1) == std::vector<int>{T, T + 1});
  // Layer 2 adds the quads sharing a node with them: cells (2, 0), (0..2, 1).
  CHECK(moving_region(b.m, b.moving, 2) == std::vector<int>{T, T + 1, T + 2, T + 3, T + 4, T + 5});
  // reach 1: within one cell size of the two cells' centroids, all quads.
  const std::vector<int> reach = reach_region(b.m, b.moving, 1);
  CHECK(std::is_sorted(reach.begin(), reach.end()));
  CHECK(std::find(reach.begin(), reach.end(), T) != reach.end());
  CHECK(std::find(reach.begin(), reach.end(), T + 1) != reach.end());
  CHECK(reach.front() >= T);
  // The linear mesh's nodes: the 7 x 7 cell corners, quadrilaterals' included.
  const std::vector<bool> vertex = vertex_nodes(b.m);
  CHECK(std::count(vertex.begin(), vertex.end(), true) == 49);
  CHECK(vertex[b.m.quad(0, 0)]);
  CHECK(!vertex[b.m.quad(12, 0)]);

  // Solved on quadrilateral 1 alone: quadrilateral 0's moving nodes go to their
  // targets, the rest of the mesh stays; the result is certified.
  DeformOptions o;
  o.region = {T + 1};
  const DeformResult r = deform_mesh(b.m, b.target, b.prescribed, o);
  CHECK(r.complete);
  CHECK(r.solved_triangles == 1);
  CHECK(r.worst_ratio > 0);
  CHECK(r.worst_ratio == Approx(mesh_validity(r.mesh).worst));
  double off_target = 0;
  int moved_outside = 0;
  std::vector<bool> in_region(b.m.num_nodes(), false);
  for (Eigen::Index i = 0; i < b.m.quad.rows(); ++i) in_region[b.m.quad(i, 1)] = true;
  for (int i = 0; i < b.m.num_nodes(); ++i) {
    if (b.prescribed[i])
      off_target = std::max(off_target, (r.mesh.x.col(i) - b.target.col(i)).norm());
    if (!b.prescribed[i] && !in_region[i]) moved_outside += r.mesh.x.col(i) != b.m.x.col(i);
  }
  CHECK(off_target < 1e-12);
  CHECK(moved_outside == 0);
  // Quad 1's own interior nodes moved.
  CHECK((r.mesh.x.col(b.m.quad(12, 1)) - b.m.x.col(b.m.quad(12, 1))).norm() > 1e-3);

  o.region = {T + 1, b.m.num_elements_2d()};
  CHECK_THROWS_WITH(deform_mesh(b.m, b.target, b.prescribed, o),
                    Catch::Contains("region element 54 out of range 0..53"));
}

TEST_CASE("a boundary layer of quadrilaterals curved onto its circle, triangles outside, p = 2, 3",
          "[curving][quad]") {
  // The quarter annulus 1 <= r <= 2 in 6 by 6 cells graded as r = 1 + s^3
  // (first layer 1/216 thick against a chord sag of 1 - cos(pi/24) = 0.0086),
  // straight-sided: quadrilaterals in the two layers at the inner circle (or
  // everywhere), triangles outside; the nodes of both circles moved onto them.
  // Put there alone they invert the first layer; the analogy (the curve
  // stage's defaults) keeps minJ/maxJ >= 0.9 on the mixed mesh, and on the
  // quad mesh within 5 % of its straight-sided start (bilinear cells of an
  // annulus, whose det J varies: 0.79).
  auto corner = [](const Eigen::Vector2d& y) {
    const double r = 1 + std::pow(y(0), 3.0), t = M_PI / 2 * y(1);
    return Eigen::Vector2d(r * std::cos(t), r * std::sin(t));
  };
  for (int p : {2, 3})
    for (int quad_columns : {2, 6}) {
      INFO("p = " << p << ", quad columns " << quad_columns);
      const Mesh param = fem_test::mixed_square(6, p, quad_columns);
      Mesh m = fem_test::mixed_square(6, p, quad_columns, corner);
      if (quad_columns == 6) m.tri.resize(0, 0);  // quadrilaterals alone, no triangle matrix
      Eigen::Matrix2Xd target = m.x;
      const std::vector<bool> prescribed = boundary_nodes(m);
      for (int i = 0; i < m.num_nodes(); ++i) {
        const double s = param.x(0, i);
        if (std::abs(s) < 1e-12 || std::abs(s - 1) < 1e-12)
          target.col(i) = (1 + s) * m.x.col(i).normalized();
      }
      Mesh placed = m;
      placed.x = target;
      REQUIRE(mesh_validity(placed).invalid > 0);
      const DeformResult r = deform_mesh(m, target, prescribed);
      CHECK(r.complete);
      if (quad_columns == 2)
        CHECK(r.worst_ratio > 0.9);
      else
        CHECK(r.worst_ratio > 0.95 * mesh_validity(m).worst);
      double off_circle = 0;
      for (int i = 0; i < m.num_nodes(); ++i)
        if (std::abs(param.x(0, i)) < 1e-12)
          off_circle = std::max(off_circle, std::abs(r.mesh.x.col(i).norm() - 1));
      CHECK(off_circle < 1e-12);
    }
}
