// The high-order optimiser on quadrilaterals and on mixed meshes (2D elements
// indexed triangles first, then quadrilaterals: core/mesh.h): a displaced
// interior vertex is moved back, every element stays certified valid.
#include <Eigen/LU>
#include <catch2/catch.hpp>
#include <cmath>

#include "../fem/fem_test_support.h"
#include "curving/deform_mesh.h"
#include "curving/distortion_energy.h"
#include "curving/optimisation_patches.h"
#include "curving/optimise_mesh.h"
#include "element/quad_reference_nodes.h"
#include "fem/element_tabulation.h"
#include "quality/mesh_validity.h"

using namespace homesh;

namespace {

// The n by n cells of the unit square at order p (the first quad_columns
// columns quadrilaterals, the rest triangles: fem_test::mixed_square), every
// element straight-sided, with the cell corner at `from` moved by `by`.
Mesh displaced(int n, int p, int quad_columns, const Eigen::Vector2d& from,
               const Eigen::Vector2d& by) {
  return fem_test::mixed_square(n, p, quad_columns, [&](const Eigen::Vector2d& y) {
    return Eigen::Vector2d((y - from).norm() < 1e-12 ? Eigen::Vector2d(y + by) : y);
  });
}

int node_at(const Mesh& m, const Eigen::Vector2d& y) {
  for (int i = 0; i < m.num_nodes(); ++i)
    if ((m.x.col(i) - y).norm() < 1e-12) return i;
  return -1;
}

}  // namespace

TEST_CASE("optimise quads: distortion energy 0 on parallelograms, gradient by differences",
          "[curving][quad]") {
  for (int p : {1, 2, 3}) {
    CAPTURE(p);
    const ElementTabulation tab = tabulate_quad_element_and_lattice(p, 2 * p, 0.2);
    REQUIRE(tab.quad);
    REQUIRE(tab.rule.weights.sum() == Approx(1.0));  // the square's area
    // A straight parallelogram: its Jacobian J0 everywhere.
    const Eigen::Matrix2Xd ref = quad_reference_nodes(p);
    Eigen::Matrix2d J0;
    J0 << 2.0, 0.7, 0.3, 1.5;
    const Eigen::Matrix2Xd X = J0 * ref;
    const DistortionEnergyOptions opt;
    CHECK(distortion_energy(X, tab, J0.inverse(), opt) == Approx(0).margin(1e-12));
    // The unit square against its ideal target (W = J = I).
    CHECK(distortion_energy(ref, tab, Eigen::Matrix2d::Identity(), opt) == Approx(0).margin(1e-12));
    CHECK(distortion_energy(X, tab, Eigen::Matrix2d::Identity(), opt) > 0.01);
    // A curved, non-parallelogram element: the analytic gradient against central differences.
    Eigen::Matrix2Xd Y = X;
    for (int k = 0; k < Y.cols(); ++k)
      Y.col(k) += 0.05 * Eigen::Vector2d(std::sin(3.0 * k + 1), std::cos(5.0 * k));
    Eigen::Matrix2Xd g;
    const double E = distortion_energy(Y, tab, J0.inverse(), opt, &g);
    REQUIRE(std::isfinite(E));
    REQUIRE(E > 0);
    const double h = 1e-6;
    for (int k = 0; k < Y.cols(); ++k)
      for (int c = 0; c < 2; ++c) {
        Eigen::Matrix2Xd Yp = Y, Ym = Y;
        Yp(c, k) += h;
        Ym(c, k) -= h;
        const double fd = (distortion_energy(Yp, tab, J0.inverse(), opt) -
                           distortion_energy(Ym, tab, J0.inverse(), opt)) /
                          (2 * h);
        CHECK(g(c, k) == Approx(fd).epsilon(1e-5).margin(1e-6 * E));
      }
  }
}

TEST_CASE("optimise quads: patches grow through nodes shared by triangles and quadrilaterals",
          "[curving][quad]") {
  // 4 by 4 cells of order 2, quadrilaterals in the first two columns (2D elements 16..23),
  // triangles beyond (0..15).
  const Mesh m = fem_test::mixed_square(4, 2, 2);
  REQUIRE(m.num_triangles() == 16);
  REQUIRE(m.num_quads() == 8);
  std::vector<bool> poor(m.num_elements_2d(), false);
  poor[16] = true;  // the quadrilateral of cell (0, 0)
  const std::vector<bool> held = boundary_nodes(m);
  const std::vector<OptimisationPatch> none = optimisation_patches(m, poor, 0, held);
  // Alone, the corner cell has no free node but its own interior node.
  REQUIRE(none.size() == 1);
  CHECK(none[0].elements == std::vector<int>{16});
  CHECK(none[0].free_nodes.size() == 1);
  // Two rings: cells (0..2, 0..2), the triangles of column 2 included.
  const std::vector<OptimisationPatch> two = optimisation_patches(m, poor, 2, held);
  REQUIRE(two.size() == 1);
  CHECK(two[0].elements.front() < m.num_triangles());
  CHECK(two[0].elements.back() >= m.num_triangles());
  // 6 quadrilaterals, the 6 triangles of cells (2, 0..2) (a corner on x = 1/2, y <= 1/2).
  CHECK(two[0].elements.size() == 6 + 6);
}

TEST_CASE("optimise quads: a displaced interior vertex of a quadrilateral grid goes back",
          "[curving][quad]") {
  const Eigen::Vector2d centre(0.5, 0.5), by(0.08, -0.05);  // 0.32 and 0.2 cell sizes
  for (int p : {1, 2}) {
    CAPTURE(p);
    const Mesh m = displaced(4, p, 4, centre, by);
    REQUIRE(m.num_quads() == 16);
    REQUIRE(m.num_triangles() == 0);
    const MeshValidity start = mesh_validity(m);
    REQUIRE(start.invalid == 0);
    REQUIRE(start.worst < 0.7);
    OptimiseOptions opt;
    opt.free_vertices = true;
    opt.threshold = 0.99;
    for (auto target : {OptimiseOptions::Target::ideal, OptimiseOptions::Target::straight}) {
      opt.target = target;
      const OptimiseResult r = optimise_mesh(m, boundary_nodes(m), opt);
      const MeshValidity after = mesh_validity(r.mesh);
      const int v = node_at(m, centre + by);
      REQUIRE(v >= 0);
      INFO((target == OptimiseOptions::Target::ideal ? "ideal" : "straight")
           << " worst " << start.worst << " -> " << after.worst << ", vertex at "
           << r.mesh.x.col(v).transpose());
      CHECK(after.invalid == 0);
      CHECK(r.poor_before == 4);
      CHECK(r.worst_before == Approx(start.worst));
      CHECK(r.worst_after == Approx(after.worst));
      CHECK(r.accepted == r.patches);
      const double off = (r.mesh.x.col(v) - centre).norm();
      if (target == OptimiseOptions::Target::ideal) {
        // The unit square is the ideal element: the uniform grid is the optimum.
        CHECK(after.worst > 0.999);     // measured 0.999999 (p = 1), 0.99995 (p = 2)
        CHECK(off < 0.01 * by.norm());  // measured 1e-5, 4e-4 of the displacement
      } else {
        // The straight target is each element's start (distorted) shape: only the size
        // term pulls the vertex back, and at p = 2 the edges bend to even det J.
        CHECK(after.worst > 0.95);     // measured 0.957, 0.956
        CHECK(off < 0.6 * by.norm());  // measured 0.17, 0.49 of the displacement
      }
    }
  }
}

TEST_CASE("optimise quads: a vertex shared by quadrilaterals and triangles", "[curving][quad]") {
  // 4 by 4 cells, quadrilaterals in x < 1/2, triangles beyond; the vertex (1/2, 1/2) is a
  // corner of two quadrilaterals and of three triangles.
  const Eigen::Vector2d centre(0.5, 0.5), by(-0.07, 0.06);
  for (int p : {1, 2, 3}) {
    CAPTURE(p);
    const Mesh m = displaced(4, p, 2, centre, by);
    const MeshValidity start = mesh_validity(m);
    REQUIRE(start.invalid == 0);
    OptimiseOptions opt;
    opt.free_vertices = true;
    opt.threshold = 0.93;
    const OptimiseResult r = optimise_mesh(m, boundary_nodes(m), opt);
    const MeshValidity after = mesh_validity(r.mesh);
    const int v = node_at(m, centre + by);
    INFO("worst " << start.worst << " -> " << after.worst << ", vertex at "
                  << r.mesh.x.col(v).transpose());
    CHECK(after.invalid == 0);
    CHECK(r.worst_after == Approx(after.worst));
    CHECK(start.worst < 0.5);   // measured 0.48
    CHECK(after.worst > 0.93);  // measured 0.936 (p = 1), 0.953 (p = 2), 0.955 (p = 3)
    CHECK(r.poor_after == 0);
    CHECK((r.mesh.x.col(v) - centre).norm() < 0.8 * by.norm());  // measured 0.30, 0.68, 0.75
  }
}
