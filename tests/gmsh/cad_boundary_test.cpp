#include "gmsh/cad_boundary.h"

#include <gmsh.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "../support/gmsh_session.h"
#include "core/raise_order.h"
#include "gmsh/read_model.h"

using namespace homesh;

TEST_CASE("boundary nodes land on the CAD circle, equally spaced in arc length", "[gmsh]") {
  test::GmshSession session;
  gmsh::open(std::string(HOMESH_SOURCE_DIR) + "/geo/plate_hole.geo");
  gmsh::model::mesh::generate(2);
  for (int p : {2, 4, 6}) {
    CAPTURE(p);
    Mesh m = raise_order(gmsh_adapter::read_model("plate_hole"), p);
    const Eigen::Matrix2Xd x = gmsh_adapter::place_on_cad(m);
    int on_hole = 0;
    double worst_radius = 0, worst_spacing = 0, worst_straight = 0;
    for (int k = 0; k < m.num_lines(); ++k) {
      const Eigen::Vector2d a = x.col(m.line(0, k)), b = x.col(m.line(1, k));
      const bool hole = std::abs(a.norm() - 0.5) < 1e-9 && std::abs(b.norm() - 0.5) < 1e-9;
      double angle = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
      for (int j = 2; j <= p; ++j) {
        const Eigen::Vector2d q = x.col(m.line(j, k));
        if (hole) {
          ++on_hole;
          worst_radius = std::max(worst_radius, std::abs(q.norm() - 0.5));
          const double t = std::atan2(a.x() * q.y() - a.y() * q.x(), a.dot(q)) / angle;
          worst_spacing = std::max(worst_spacing, std::abs(t - (j - 1.0) / p));
          REQUIRE(m.node_class[m.line(j, k)].dim == 1);
          REQUIRE(std::isfinite(m.node_class[m.line(j, k)].u));
        } else {  // straight farfield sides: placement = the straight-sided node
          worst_straight = std::max(worst_straight, (q - m.x.col(m.line(j, k))).norm());
        }
      }
    }
    REQUIRE(on_hole > 0);
    CHECK(worst_radius < 1e-12);
    CHECK(worst_spacing < 1e-3);  // arc length tabulated with 64 chords
    CHECK(worst_straight < 1e-12);
  }
}
