// Our certified minJ/maxJ of quadrilaterals against Gmsh's AnalyseMeshQuality
// plugin on the same mixed meshes (a boundary layer of quadrilaterals round a
// hole, triangles elsewhere), orders 1-4: every non-corner node jittered, then
// elements pushed to just before and just past the loss of validity.
#include <gmsh.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <set>

#include "../support/gmsh_session.h"
#include "gmsh/read_model.h"
#include "gmsh/write_model.h"
#include "quality/jacobian_bounds.h"
#include "quality/mesh_validity.h"

using namespace homesh;

namespace {

// The 2D elements (core/mesh.h numbering) holding node i.
std::vector<int> elements_of(const Mesh& m, int i) {
  std::vector<int> out;
  for (int e = 0; e < m.num_triangles(); ++e)
    if ((m.tri.col(e).array() == i).any()) out.push_back(e);
  for (int e = 0; e < m.num_quads(); ++e)
    if ((m.quad.col(e).array() == i).any()) out.push_back(m.num_triangles() + e);
  return out;
}

bool all_valid(const Mesh& m, const std::vector<int>& elements) {
  for (int e : elements) {
    const bool quad = e >= m.num_triangles();
    const int k = quad ? e - m.num_triangles() : e;
    const JacobianBounds b = quad ? quad_jacobian_bounds(m.quad_nodes(k), m.order)
                                  : jacobian_bounds(m.triangle_nodes(k), m.order);
    if (!b.valid_certified) return false;
  }
  return true;
}

// Moves node i along `d` to `factor` times the distance at which one of its
// elements stops being valid (bisection on our certificate).
void push_to_threshold(Mesh& m, int i, const Eigen::Vector2d& d, double factor) {
  const std::vector<int> elements = elements_of(m, i);
  const Eigen::Vector2d x0 = m.x.col(i);
  double lo = 0, hi = 1;
  for (int it = 0; it < 40; ++it) {
    const double t = 0.5 * (lo + hi);
    m.x.col(i) = x0 + t * d;
    (all_valid(m, elements) ? lo : hi) = t;
  }
  m.x.col(i) = x0 + factor * 0.5 * (lo + hi) * d;
}

}  // namespace

TEST_CASE("quadrilateral minJ/maxJ matches Gmsh's AnalyseMeshQuality, same elements flagged",
          "[gmsh][quads]") {
  int compared = 0;
  for (const bool all_quads : {false, true})
    for (int p = 1; p <= 4; ++p) {
      CAPTURE(all_quads, p);
      test::GmshSession session;
      test::make_plate_with_quad_layer(p, 0.1, all_quads);
      Mesh m = gmsh_adapter::read_model("plate");
      REQUIRE(m.num_quads() > 20);
      std::mt19937 rng(11 + p);
      std::uniform_real_distribution<double> jitter(-1.0, 1.0);
      // Jitter every non-corner surface node by up to 30 % of the finest
      // layer's thickness over p (the layer's first cell is 0.01 thick).
      std::vector<bool> corner(m.num_nodes(), false);
      for (int e = 0; e < m.num_triangles(); ++e)
        for (int k = 0; k < 3; ++k) corner[m.tri(k, e)] = true;
      for (int e = 0; e < m.num_quads(); ++e)
        for (int k = 0; k < 4; ++k) corner[m.quad(k, e)] = true;
      for (int i = 0; i < m.num_nodes(); ++i)
        if (!corner[i] && m.node_class[i].dim == 2)
          m.x.col(i) += 0.003 / p * Eigen::Vector2d(jitter(rng), jitter(rng));
      // Quadrilaterals pushed to 0.98 (just valid) or 1.02 (just invalid) of the
      // move that breaks them: an interior node of the quadrilateral (p >= 2) or
      // a corner in the surface (p = 1), elements not shared between pushes.
      std::set<int> touched;
      int pushes = 0;
      for (int q = 0; q < m.num_quads() && pushes < 12; ++q) {
        const int i = m.quad(p >= 2 ? 4 * p : 0, q);
        if (m.node_class[i].dim != 2) continue;
        const std::vector<int> around = elements_of(m, i);
        if (!all_valid(m, around) ||
            std::any_of(around.begin(), around.end(), [&](int e) { return touched.count(e); }))
          continue;
        touched.insert(around.begin(), around.end());
        const double angle = jitter(rng) * M_PI;
        push_to_threshold(m, i, 0.2 * Eigen::Vector2d(std::cos(angle), std::sin(angle)),
                          pushes % 2 == 0 ? 0.98 : 1.02);
        ++pushes;
      }
      REQUIRE(pushes >= 6);
      const auto tags = gmsh_adapter::write_model(m);

      std::vector<std::size_t> element_tags;
      std::vector<std::vector<double>> data;
      REQUIRE(homesh::test::analyse_mesh_quality(element_tags, data));
      REQUIRE(element_tags.size() == static_cast<std::size_t>(m.num_elements_2d()));

      const MeshValidity v = mesh_validity(m);
      int invalid_gmsh = 0, invalid_ours = 0, disagree = 0, near = 0;
      double worst_gap = 0;
      for (std::size_t k = 0; k < element_tags.size(); ++k) {
        const int e =
            static_cast<int>(std::find(tags.element.begin(), tags.element.end(), element_tags[k]) -
                             tags.element.begin());
        const double ours = v.ratio(e), theirs = data[k][0];
        compared += e >= m.num_triangles() ? 1 : 0;
        worst_gap = std::max(worst_gap, std::abs(ours - theirs));
        invalid_gmsh += theirs <= 0 ? 1 : 0;
        invalid_ours += v.min_det(e) <= 0 ? 1 : 0;
        near += std::abs(theirs) < 0.05 ? 1 : 0;
        disagree += (theirs <= 0) != (v.min_det(e) <= 0) ? 1 : 0;
      }
      INFO("quadrilaterals " << m.num_quads() << ", triangles " << m.num_triangles() << ", invalid "
                             << invalid_gmsh << ", near 0 " << near << ", largest |ours - Gmsh's| "
                             << worst_gap);
      // Both refine the Bezier bounds of det J to 1e-3 of max |det J| (Gmsh's
      // default and ours), so each ratio is within about 2e-3 of the true one.
      CHECK(worst_gap < 2e-3);
      REQUIRE(disagree == 0);
      REQUIRE(invalid_ours == invalid_gmsh);
      REQUIRE(v.invalid == invalid_gmsh);
      REQUIRE(invalid_gmsh >= pushes / 2);  // the pushes past the threshold did break them
      REQUIRE(near >= pushes);              // and those before it are valid by a hair
    }
  CHECK(compared > 500);
}
