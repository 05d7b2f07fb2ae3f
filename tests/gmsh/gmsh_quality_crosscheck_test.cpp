// Our certified minJ/maxJ against Gmsh's own AnalyseMeshQuality plugin on the
// same meshes, orders 1-4, with some elements made invalid on purpose.
#include <gmsh.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <random>

#include "../support/gmsh_session.h"
#include "gmsh/read_model.h"
#include "gmsh/write_model.h"
#include "quality/mesh_validity.h"

using namespace homesh;

TEST_CASE("minJ/maxJ matches Gmsh's AnalyseMeshQuality, invalid flagged by both", "[gmsh]") {
  for (int p = 1; p <= 4; ++p) {
    CAPTURE(p);
    test::GmshSession session;
    test::make_plate_with_hole(p, 0.15);
    Mesh m = gmsh_adapter::read_model("plate");
    // Jitter every non-corner interior node by up to 40 % of its element size.
    std::mt19937 rng(7 + p);
    std::uniform_real_distribution<double> jitter(-0.4, 0.4);
    std::vector<bool> corner(m.num_nodes(), false);
    for (int e = 0; e < m.num_triangles(); ++e)
      for (int k = 0; k < 3; ++k) corner[m.tri(k, e)] = true;
    for (int i = 0; i < m.num_nodes(); ++i)
      if (!corner[i] && m.node_class[i].dim == 2)
        m.x.col(i) += 0.15 / p * Eigen::Vector2d(jitter(rng), jitter(rng));
    const auto tags = gmsh_adapter::write_model(m);

    std::vector<std::size_t> element_tags;
    std::vector<std::vector<double>> data;
    REQUIRE(homesh::test::analyse_mesh_quality(element_tags, data));
    REQUIRE(element_tags.size() == static_cast<std::size_t>(m.num_triangles()));

    const MeshValidity v = mesh_validity(m);
    int invalid_gmsh = 0, disagree = 0;
    double worst_gap = 0;
    for (std::size_t k = 0; k < element_tags.size(); ++k) {
      const int e = static_cast<int>(element_tags[k] - tags.first_triangle);
      const double ours = v.ratio(e), theirs = data[k][0];
      worst_gap = std::max(worst_gap, std::abs(ours - theirs));
      invalid_gmsh += theirs <= 0 ? 1 : 0;
      disagree += (theirs <= 0) != (v.min_det(e) <= 0) ? 1 : 0;
    }
    // Both refine the Bezier bounds to 1e-3 of max |det J|; their ratios agree
    // to that tolerance (relative to the ratio's scale 1).
    CHECK(worst_gap < 2e-3);
    REQUIRE(disagree == 0);
    REQUIRE(v.invalid == invalid_gmsh);
    if (p >= 2) REQUIRE(invalid_gmsh > 0);  // the jitter did make invalid elements
  }
}
