#include "core/raise_volume_order.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <set>

#include "core/error.h"
#include "element/tet_reference_nodes.h"
#include "quality/volume_validity.h"
#include "two_tetrahedra.h"

using namespace homesh;

namespace {

// The affine map of tetrahedron e's corners at reference point (u, v, w).
Eigen::Vector3d affine(const VolumeMesh& m, int e, const Eigen::Vector3d& r) {
  const Eigen::Vector3d a = m.x.col(m.tet(0, e));
  return a + r(0) * (m.x.col(m.tet(1, e)) - a) + r(1) * (m.x.col(m.tet(2, e)) - a) +
         r(2) * (m.x.col(m.tet(3, e)) - a);
}

}  // namespace

TEST_CASE("raise_volume_order node count is V + (p-1) E + (p-1)(p-2)/2 F + (p-1)(p-2)(p-3)/6 T",
          "[core][raise_volume_order]") {
  const VolumeMesh m = test::two_tetrahedra();
  for (int p = 1; p <= kMaxTetrahedronOrder; ++p) {
    INFO("p = " << p);
    const VolumeMesh r = raise_volume_order(m, p);
    CHECK(r.order == p);
    CHECK(r.num_nodes() ==
          5 + (p - 1) * 9 + (p - 1) * (p - 2) / 2 * 7 + (p - 1) * (p - 2) * (p - 3) / 6 * 2);
    CHECK(r.tet.rows() == tetrahedron_node_count(p));
    CHECK(r.tri.rows() == (p + 1) * (p + 2) / 2);
    CHECK(r.line.rows() == p + 1);
    // The corners keep their indices; nothing is left unused.
    CHECK(r.tet.topRows<4>() == m.tet);
    std::set<int> used(r.tet.data(), r.tet.data() + r.tet.size());
    CHECK(static_cast<int>(used.size()) == r.num_nodes());
  }
}

TEST_CASE("raise_volume_order places every node at its element's affine map, shared ones once",
          "[core][raise_volume_order]") {
  const VolumeMesh m = test::two_tetrahedra();
  for (int p = 2; p <= kMaxTetrahedronOrder; ++p) {
    INFO("p = " << p);
    const VolumeMesh r = raise_volume_order(m, p);
    const Eigen::Matrix3Xd ref = tetrahedron_nodes(p);
    double worst = 0;
    for (int e = 0; e < 2; ++e)
      for (Eigen::Index k = 0; k < ref.cols(); ++k)
        worst = std::max(worst, (r.x.col(r.tet(k, e)) - affine(m, e, ref.col(k))).norm());
    CHECK(worst < 1e-14);
    // The shared face 1-2-3 holds (p-1)(p-2)/2 interior nodes used by both.
    std::set<int> a(r.tet.col(0).data(), r.tet.col(0).data() + r.tet.rows());
    int shared = 0;
    for (Eigen::Index k = 0; k < r.tet.rows(); ++k) shared += a.count(r.tet(k, 1)) ? 1 : 0;
    CHECK(shared == triangle_node_count(p));
    // The triangle's nodes are nodes of the first tetrahedron, at the same places.
    for (Eigen::Index k = 0; k < r.tri.rows(); ++k) CHECK(a.count(r.tri(k, 0)) == 1);
    // Straight-sided: det J is 6 times the volume, so minJ/maxJ is 1.
    const MeshValidity v = volume_validity(r);
    CHECK(v.invalid == 0);
    CHECK(v.worst == Approx(1.0).margin(1e-9));
  }
}

TEST_CASE("raise_volume_order classifies new nodes on the line, the triangle, else the volume",
          "[core][raise_volume_order]") {
  const VolumeMesh m = test::two_tetrahedra();
  const int p = 4;
  const VolumeMesh r = raise_volume_order(m, p);
  for (Eigen::Index k = 2; k < r.line.rows(); ++k) {
    const VolumeNodeClass& c = r.node_class[r.line(k, 0)];
    CHECK(c.dim == 1);
    CHECK(c.tag == 4);
    // u interpolated between the ends (0 and 2) at the node's place along the line.
    CHECK(c.u == Approx(2.0 * r.x(0, r.line(k, 0)) / 2.0).margin(1e-12));
  }
  int on_surface = 0;
  for (Eigen::Index k = 3; k < r.tri.rows(); ++k) {
    const VolumeNodeClass& c = r.node_class[r.tri(k, 0)];
    if (c.dim == 1) continue;  // the nodes of edge 0-1
    ++on_surface;
    CHECK(c.dim == 2);
    CHECK(c.tag == 5);
    // Corners 0 and 1 sit on the curve, not the surface: no surface parameters to interpolate.
    CHECK(std::isnan(c.u));
  }
  CHECK(on_surface == 2 * (p - 1) + (p - 1) * (p - 2) / 2);
  int inside = 0;
  for (const VolumeNodeClass& c : r.node_class) inside += c.dim == 3 && c.tag == 1 ? 1 : 0;
  // Edges not on the triangle: 9 - 3; faces: 7 - 1; interiors: 2; plus the 2 old corners.
  CHECK(inside ==
        2 + 6 * (p - 1) + 6 * (p - 1) * (p - 2) / 2 + 2 * (p - 1) * (p - 2) * (p - 3) / 6);
  CHECK(r.physicals.size() == 1);
  CHECK(r.entities.size() == 3);
}

TEST_CASE("raise_volume_order lowers back to the corners and refuses orders out of range",
          "[core][raise_volume_order]") {
  const VolumeMesh m = test::two_tetrahedra();
  const VolumeMesh back = raise_volume_order(raise_volume_order(m, 3), 1);
  CHECK(back.x == m.x);
  CHECK(back.tet == m.tet);
  CHECK(back.tri == m.tri);
  CHECK(back.line == m.line);
  CHECK_THROWS_AS(raise_volume_order(m, 0), Error);
  CHECK_THROWS_WITH(raise_volume_order(m, kMaxTetrahedronOrder + 1),
                    Catch::Contains("order p = 6 is out of range"));
}
