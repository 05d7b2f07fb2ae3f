// Our certified minJ/maxJ of tetrahedra (quality/jacobian_bounds.h) against Gmsh's
// own AnalyseMeshQuality plugin on the same perturbed meshes, orders 1-4 (issue 24).
#include <gmsh.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <random>

#include "../support/gmsh_session.h"
#include "core/mesh.h"
#include "quality/jacobian_bounds.h"

using namespace homesh;

TEST_CASE("tetrahedra: minJ/maxJ matches Gmsh's AnalyseMeshQuality, invalid flagged by both",
          "[gmsh]") {
  for (int p = 1; p <= 4; ++p) {
    CAPTURE(p);
    test::GmshSession session;
    gmsh::model::add("box");
    gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
    gmsh::model::occ::synchronize();
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.3);
    gmsh::model::mesh::generate(3);
    if (p > 1) gmsh::model::mesh::setOrder(p);
    const int type = gmsh::model::mesh::getElementType("Tetrahedron", p);
    std::vector<std::size_t> tets, conn;
    gmsh::model::mesh::getElementsByType(type, tets, conn);
    REQUIRE(tets.size() > 100);
    // Move every node but the tetrahedra's corners by up to 12 % of the size over p.
    std::vector<std::size_t> node_tags;
    std::vector<double> xyz, param;
    gmsh::model::mesh::getNodes(node_tags, xyz, param);
    std::map<std::size_t, Eigen::Vector3d> x;
    for (std::size_t i = 0; i < node_tags.size(); ++i)
      x[node_tags[i]] = Eigen::Vector3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    const int n = tetrahedron_node_count(p);
    std::map<std::size_t, bool> corner;
    for (std::size_t e = 0; e < tets.size(); ++e)
      for (int k = 0; k < 4; ++k) corner[conn[n * e + k]] = true;
    std::mt19937 rng(3 + p);
    std::uniform_real_distribution<double> jitter(-0.12, 0.12);
    for (auto& [tag, y] : x) {
      if (corner.count(tag)) continue;
      y += 0.3 / p * Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
      gmsh::model::mesh::setNode(tag, {y(0), y(1), y(2)}, {});
    }

    std::vector<std::size_t> element_tags;
    std::vector<std::vector<double>> data;
    gmsh::plugin::setNumber("AnalyseMeshQuality", "DimensionOfElements", 3);
    REQUIRE(homesh::test::analyse_mesh_quality(element_tags, data));
    REQUIRE(element_tags.size() == tets.size());
    std::map<std::size_t, std::size_t> index;
    for (std::size_t e = 0; e < tets.size(); ++e) index[tets[e]] = e;

    int invalid_gmsh = 0, invalid_ours = 0, disagree = 0;
    double worst_gap = 0;
    for (std::size_t k = 0; k < element_tags.size(); ++k) {
      const std::size_t e = index.at(element_tags[k]);
      Eigen::Matrix3Xd X(3, n);
      for (int i = 0; i < n; ++i) X.col(i) = x.at(conn[n * e + i]);
      const JacobianBounds b = tetrahedron_jacobian_bounds(X, p);
      const double ours = scaled_jacobian_ratio(b), theirs = data[k][0];
      worst_gap = std::max(worst_gap, std::abs(ours - theirs));
      invalid_gmsh += theirs <= 0;
      invalid_ours += !b.valid_certified;
      disagree += (theirs <= 0) != !b.valid_certified;
    }
    // Both refine the Bezier bounds to 1e-3 of max |det J|.
    INFO("invalid " << invalid_gmsh << " of " << tets.size() << ", gap " << worst_gap);
    CHECK(worst_gap < 2e-3);
    CHECK(disagree == 0);
    CHECK(invalid_ours == invalid_gmsh);
    if (p >= 2) CHECK(invalid_gmsh > 0);  // the jitter did make invalid elements
    if (p >= 2) CHECK(invalid_gmsh < static_cast<int>(tets.size()));
  }
}
