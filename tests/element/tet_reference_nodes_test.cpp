#include "element/tet_reference_nodes.h"

#include <catch2/catch.hpp>
#include <set>
#include <tuple>

#include "../support/node_rows.h"
#include "core/error.h"
#include "core/mesh.h"

using namespace homesh;

TEST_CASE("tetrahedron_nodes equal Gmsh's tetrahedron nodes bit for bit, p = 1..8",
          "[element][reference_nodes]") {
  const auto rows =
      homesh::test::node_rows(HOMESH_SOURCE_DIR "/tests/element/gmsh_reference_nodes.txt");
  for (int p = 1; p <= 8; ++p) {
    INFO("p = " << p);
    const std::vector<double>& gmsh = rows.at({"Tetrahedron", p});
    const Eigen::Matrix3Xd nodes = tetrahedron_nodes(p);
    REQUIRE(nodes.cols() == tetrahedron_node_count(p));
    REQUIRE(gmsh.size() == static_cast<std::size_t>(nodes.size()));
    for (Eigen::Index k = 0; k < nodes.cols(); ++k) {
      INFO("node " << k);
      for (int r = 0; r < 3; ++r) CHECK(nodes(r, k) == gmsh[3 * k + r]);
    }
  }
}

TEST_CASE("tetrahedron_node_indices: every lattice point once, corners then edges in order",
          "[element][reference_nodes]") {
  for (int p = 1; p <= kMaxOrder; ++p) {
    const Eigen::Matrix3Xi ijl = tetrahedron_node_indices(p);
    std::set<std::tuple<int, int, int>> seen;
    for (Eigen::Index k = 0; k < ijl.cols(); ++k) {
      CHECK(ijl.col(k).minCoeff() >= 0);
      CHECK(ijl.col(k).sum() <= p);
      seen.insert({ijl(0, k), ijl(1, k), ijl(2, k)});
    }
    CHECK(static_cast<int>(seen.size()) == tetrahedron_node_count(p));
    // Edge 3-0's nodes run from corner 3 down to corner 0: (0, 0, p - 1) first.
    if (p >= 2) CHECK(ijl.col(4 + 3 * (p - 1)) == Eigen::Vector3i(0, 0, p - 1));
  }
  CHECK_THROWS_AS(tetrahedron_node_indices(0), Error);
  CHECK_THROWS_AS(tetrahedron_nodes(-1), Error);
}
