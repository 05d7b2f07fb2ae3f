#include "element/quad_reference_nodes.h"

#include <catch2/catch.hpp>

#include "../support/node_rows.h"
#include "core/error.h"
#include "core/mesh.h"

using namespace homesh;

TEST_CASE("quad_reference_nodes are Gmsh's quadrilateral nodes mapped to [0, 1]^2, p = 1..8",
          "[element][quad_reference_nodes]") {
  const auto rows =
      homesh::test::node_rows(HOMESH_SOURCE_DIR "/tests/element/gmsh_reference_nodes.txt");
  for (int p = 1; p <= 8; ++p) {
    INFO("p = " << p);
    const std::vector<double>& gmsh = rows.at({"Quadrilateral", p});
    const Eigen::Matrix2Xd nodes = quad_reference_nodes(p);
    REQUIRE(nodes.cols() == quad_node_count(p));
    REQUIRE(gmsh.size() == static_cast<std::size_t>(nodes.size()));
    for (Eigen::Index k = 0; k < nodes.cols(); ++k) {
      INFO("node " << k);
      CHECK(nodes(0, k) == Approx((gmsh[2 * k] + 1.0) / 2.0).margin(1e-15));
      CHECK(nodes(1, k) == Approx((gmsh[2 * k + 1] + 1.0) / 2.0).margin(1e-15));
    }
  }
}

TEST_CASE("quad_reference_node_indices hit each lattice point of the square once",
          "[element][quad_reference_nodes]") {
  for (int p = 1; p <= kMaxOrder; ++p) {
    INFO("p = " << p);
    const Eigen::Matrix2Xi ij = quad_reference_node_indices(p);
    Eigen::MatrixXi seen = Eigen::MatrixXi::Zero(p + 1, p + 1);
    for (Eigen::Index k = 0; k < ij.cols(); ++k) {
      REQUIRE(ij.col(k).minCoeff() >= 0);
      REQUIRE(ij.col(k).maxCoeff() <= p);
      ++seen(ij(0, k), ij(1, k));
    }
    CHECK(seen.maxCoeff() == 1);
    CHECK(seen.sum() == quad_node_count(p));
  }
  CHECK_THROWS_AS(quad_reference_node_indices(0), Error);
}
