#include "element/reference_nodes.h"

#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../support/node_rows.h"
#include "core/error.h"
#include "core/mesh.h"

using namespace homesh;

namespace {

// Rows "kind p c0 c1 ..." of gmsh_reference_nodes.txt, keyed by (kind, p).
std::map<std::pair<std::string, int>, std::vector<double>> gmsh_nodes() {
  return homesh::test::node_rows(HOMESH_SOURCE_DIR "/tests/element/gmsh_reference_nodes.txt");
}

}  // namespace

TEST_CASE("reference_nodes equal Gmsh's triangle nodes bit for bit, p = 1..8",
          "[element][reference_nodes]") {
  const auto rows = gmsh_nodes();
  for (int p = 1; p <= 8; ++p) {
    INFO("p = " << p);
    const std::vector<double>& gmsh = rows.at({"Triangle", p});
    const Eigen::Matrix2Xd nodes = reference_nodes(p);
    REQUIRE(nodes.cols() == triangle_node_count(p));
    REQUIRE(gmsh.size() == static_cast<std::size_t>(nodes.size()));
    for (Eigen::Index k = 0; k < nodes.cols(); ++k) {
      INFO("node " << k);
      CHECK(nodes(0, k) == gmsh[2 * k]);
      CHECK(nodes(1, k) == gmsh[2 * k + 1]);
    }
  }
}

TEST_CASE("reference_line_nodes are Gmsh's line nodes mapped to [0, 1], p = 1..8",
          "[element][reference_nodes]") {
  const auto rows = gmsh_nodes();
  for (int p = 1; p <= 8; ++p) {
    INFO("p = " << p);
    const std::vector<double>& gmsh = rows.at({"Line", p});
    const Eigen::RowVectorXd t = reference_line_nodes(p);
    REQUIRE(gmsh.size() == static_cast<std::size_t>(p + 1));
    for (int i = 0; i <= p; ++i) CHECK(t(i) == Approx((gmsh[i] + 1.0) / 2.0).margin(1e-15));
    // The line is the triangle's edge 0-1: same values, bit for bit.
    const Eigen::Matrix2Xd nodes = reference_nodes(p);
    CHECK(t(0) == nodes(0, 0));
    CHECK(t(1) == nodes(0, 1));
    for (int i = 1; i < p; ++i) {
      CHECK(t(i + 1) == nodes(0, 2 + i));
      CHECK(nodes(1, 2 + i) == 0.0);
    }
  }
}

TEST_CASE("reference_node_indices are the nodes times p, each lattice point once",
          "[element][reference_nodes]") {
  for (int p = 1; p <= 10; ++p) {
    INFO("p = " << p);
    const Eigen::Matrix2Xi ij = reference_node_indices(p);
    const Eigen::Matrix2Xd nodes = reference_nodes(p);
    Eigen::MatrixXi seen = Eigen::MatrixXi::Zero(p + 1, p + 1);
    for (Eigen::Index k = 0; k < ij.cols(); ++k) {
      REQUIRE(ij(0, k) >= 0);
      REQUIRE(ij(1, k) >= 0);
      REQUIRE(ij(0, k) + ij(1, k) <= p);
      ++seen(ij(0, k), ij(1, k));
      CHECK(nodes(0, k) == ij(0, k) * (1.0 / p));
      CHECK(nodes(1, k) == ij(1, k) * (1.0 / p));
    }
    CHECK(seen.maxCoeff() == 1);
    CHECK(seen.sum() == triangle_node_count(p));
  }
}

TEST_CASE("reference nodes reject orders below 1", "[element][reference_nodes]") {
  CHECK_THROWS_AS(reference_nodes(0), Error);
  CHECK_THROWS_AS(reference_node_indices(-1), Error);
  CHECK_THROWS_WITH(reference_line_nodes(0), Catch::Contains("order 0"));
}
