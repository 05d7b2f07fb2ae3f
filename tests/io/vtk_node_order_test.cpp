#include "io/vtk_node_order.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../support/node_rows.h"
#include "core/error.h"
#include "core/mesh.h"
#include "element/quad_reference_nodes.h"
#include "element/reference_nodes.h"

using namespace homesh;

namespace {

// Rows "kind p c0 c1 ..." of vtk_reference_nodes.txt (VTK 9.1's own
// parametric coordinates), keyed by (kind, p).
std::map<std::pair<std::string, int>, std::vector<double>> vtk_nodes() {
  return homesh::test::node_rows(HOMESH_SOURCE_DIR "/tests/io/vtk_reference_nodes.txt");
}

}  // namespace

TEST_CASE("vtk_triangle_node_indices are VTK's own Lagrange triangle nodes, p = 1..10",
          "[io][vtk_node_order]") {
  const auto rows = vtk_nodes();
  for (int p = 1; p <= kMaxOrder; ++p) {
    INFO("p = " << p);
    const std::vector<double>& vtk = rows.at({"Triangle", p});
    const Eigen::Matrix2Xi ij = vtk_triangle_node_indices(p);
    REQUIRE(vtk.size() == static_cast<std::size_t>(ij.size()));
    for (Eigen::Index k = 0; k < ij.cols(); ++k) {
      INFO("node " << k);
      CHECK(ij(0, k) == std::lround(vtk[2 * k] * p));
      CHECK(ij(1, k) == std::lround(vtk[2 * k + 1] * p));
      CHECK(std::abs(ij(0, k) * (1.0 / p) - vtk[2 * k]) < 1e-15);
      CHECK(std::abs(ij(1, k) * (1.0 / p) - vtk[2 * k + 1]) < 1e-15);
    }
  }
}

TEST_CASE("gmsh_to_vtk_triangle is a permutation placing each Gmsh node at its VTK position",
          "[io][vtk_node_order]") {
  const auto rows = vtk_nodes();
  for (int p = 1; p <= kMaxOrder; ++p) {
    INFO("p = " << p);
    const std::vector<int> map = gmsh_to_vtk_triangle(p);
    const int n = triangle_node_count(p);
    REQUIRE(static_cast<int>(map.size()) == n);
    std::vector<int> sorted = map;
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> all(static_cast<std::size_t>(n));
    std::iota(all.begin(), all.end(), 0);
    CHECK(sorted == all);
    // VTK node k and Gmsh node map[k] sit at the same reference point.
    const Eigen::Matrix2Xd gmsh = reference_nodes(p);
    const std::vector<double>& vtk = rows.at({"Triangle", p});
    for (int k = 0; k < n; ++k) {
      INFO("VTK node " << k << " <- Gmsh node " << map[static_cast<std::size_t>(k)]);
      CHECK(std::abs(gmsh(0, map[static_cast<std::size_t>(k)]) - vtk[2 * k]) < 1e-15);
      CHECK(std::abs(gmsh(1, map[static_cast<std::size_t>(k)]) - vtk[2 * k + 1]) < 1e-15);
    }
    // Corners first, then the p-1 nodes of edges 0-1, 1-2, 2-0, each from its first corner.
    const Eigen::Matrix2Xi ij = vtk_triangle_node_indices(p);
    CHECK(ij.col(0) == Eigen::Vector2i(0, 0));
    CHECK(ij.col(1) == Eigen::Vector2i(p, 0));
    CHECK(ij.col(2) == Eigen::Vector2i(0, p));
    for (int i = 1; i < p; ++i) {
      CHECK(ij.col(2 + i) == Eigen::Vector2i(i, 0));
      CHECK(ij.col(1 + p + i) == Eigen::Vector2i(p - i, i));
      CHECK(ij.col(2 * p + i) == Eigen::Vector2i(0, p - i));
    }
    // Then the interior, as a triangle of order p - 3 shifted by (1, 1).
    if (p >= 4) {
      const Eigen::Matrix2Xi inner = vtk_triangle_node_indices(p - 3);
      CHECK(ij.rightCols(inner.cols()) == inner.colwise() + Eigen::Vector2i(1, 1));
    } else if (p == 3) {
      CHECK(ij.col(9) == Eigen::Vector2i(1, 1));
    }
    // VTK's order is Gmsh's (element/reference_nodes.h): the map is the identity.
    CHECK(map == all);
  }
}

TEST_CASE("line_nodes_along runs from a line's first end to its second", "[io][vtk_node_order]") {
  for (int p = 1; p <= kMaxOrder; ++p) {
    INFO("p = " << p);
    const std::vector<int> along = line_nodes_along(p);
    REQUIRE(static_cast<int>(along.size()) == p + 1);
    CHECK(along.front() == 0);
    CHECK(along.back() == 1);
    // Reference positions k / p, k = 0..p, in order: every node once.
    const Eigen::RowVectorXd t = reference_line_nodes(p);
    for (int k = 0; k <= p; ++k) CHECK(std::lround(t(along[static_cast<std::size_t>(k)]) * p) == k);
  }
}

TEST_CASE("VTK node orders refuse an order below 1", "[io][vtk_node_order]") {
  CHECK_THROWS_AS(vtk_triangle_node_indices(0), Error);
  CHECK_THROWS_AS(line_nodes_along(0), Error);
}

TEST_CASE("vtk_quad_node_indices are VTK's own Lagrange quadrilateral nodes, p = 1..10",
          "[io][vtk_node_order]") {
  const auto rows = vtk_nodes();
  for (int p = 1; p <= kMaxOrder; ++p) {
    INFO("p = " << p);
    const std::vector<double>& vtk = rows.at({"Quadrilateral", p});
    const Eigen::Matrix2Xi ij = vtk_quad_node_indices(p);
    REQUIRE(vtk.size() == static_cast<std::size_t>(ij.size()));
    for (Eigen::Index k = 0; k < ij.cols(); ++k) {
      INFO("node " << k);
      CHECK(std::abs(ij(0, k) * (1.0 / p) - vtk[2 * k]) < 1e-15);
      CHECK(std::abs(ij(1, k) * (1.0 / p) - vtk[2 * k + 1]) < 1e-15);
    }
    // The map puts Gmsh's node at each VTK position, each node once.
    const std::vector<int> map = gmsh_to_vtk_quad(p);
    const Eigen::Matrix2Xi gmsh = quad_reference_node_indices(p);
    std::vector<int> sorted = map;
    std::sort(sorted.begin(), sorted.end());
    for (int k = 0; k < static_cast<int>(sorted.size()); ++k) REQUIRE(sorted[k] == k);
    for (Eigen::Index k = 0; k < ij.cols(); ++k) CHECK(gmsh.col(map[k]) == ij.col(k));
  }
}
