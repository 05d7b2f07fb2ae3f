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
#include "element/tet_reference_nodes.h"

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
  CHECK_THROWS_AS(vtk_tetrahedron_node_indices(0), Error);
  CHECK_THROWS_AS(vtk_tetrahedron_node_indices(-1), Error);
  CHECK_THROWS_AS(gmsh_to_vtk_tetrahedron(0), Error);
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

TEST_CASE("vtk_tetrahedron_node_indices are VTK own Lagrange tetrahedron nodes, p = 1..10",
          "[io][vtk_node_order]") {
  const auto rows = vtk_nodes();
  int orders = 0;
  for (const auto& [key, vtk] : rows) {
    if (key.first != "Tetrahedron") continue;
    const int p = key.second;
    INFO("p = " << p);
    ++orders;
    const Eigen::Matrix3Xi ijl = vtk_tetrahedron_node_indices(p);
    REQUIRE(ijl.cols() == tetrahedron_node_count(p));
    REQUIRE(vtk.size() == static_cast<std::size_t>(ijl.size()));
    // VTK computes (b0, b1, b2) / p (vtkHigherOrderTetra::SetParametricCoords): bit for bit.
    for (Eigen::Index k = 0; k < ijl.cols(); ++k) {
      INFO("node " << k);
      for (int d = 0; d < 3; ++d) CHECK(ijl(d, k) / static_cast<double>(p) == vtk[3 * k + d]);
    }
  }
  CHECK(orders == kMaxOrder);
}

TEST_CASE("gmsh_to_vtk_tetrahedron is a permutation placing each Gmsh node at its VTK position",
          "[io][vtk_node_order]") {
  const auto rows = vtk_nodes();
  for (int p = 1; p <= kMaxOrder; ++p) {
    INFO("p = " << p);
    const std::vector<int> map = gmsh_to_vtk_tetrahedron(p);
    const int n = tetrahedron_node_count(p);
    REQUIRE(static_cast<int>(map.size()) == n);
    std::vector<int> sorted = map;
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> all(static_cast<std::size_t>(n));
    std::iota(all.begin(), all.end(), 0);
    REQUIRE(sorted == all);
    // VTK node k and Gmsh node map[k] sit at the same reference point: the same
    // integers, and Gmsh's coordinates within rounding of VTK's own.
    const Eigen::Matrix3Xi ijl = vtk_tetrahedron_node_indices(p);
    const Eigen::Matrix3Xi gmsh_ijl = tetrahedron_node_indices(p);
    const Eigen::Matrix3Xd gmsh = tetrahedron_nodes(p);
    const std::vector<double>& vtk = rows.at({"Tetrahedron", p});
    REQUIRE(vtk.size() == static_cast<std::size_t>(3 * n));
    for (int k = 0; k < n; ++k) {
      const int g = map[static_cast<std::size_t>(k)];
      INFO("VTK node " << k << " <- Gmsh node " << g);
      CHECK(gmsh_ijl.col(g) == ijl.col(k));
      for (int d = 0; d < 3; ++d) CHECK(std::abs(gmsh(d, g) - vtk[3 * k + d]) < 1e-15);
    }
    // Corners first, then the p-1 nodes of edges 0-1, 1-2, 2-0, 0-3, 1-3, 2-3,
    // each from its first corner to its second.
    const Eigen::Vector3i corner[4] = {Eigen::Vector3i(0, 0, 0), Eigen::Vector3i(p, 0, 0),
                                       Eigen::Vector3i(0, p, 0), Eigen::Vector3i(0, 0, p)};
    for (int c = 0; c < 4; ++c) CHECK(ijl.col(c) == corner[c]);
    const int edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
    for (int e = 0; e < 6; ++e)
      for (int i = 1; i < p; ++i) {
        INFO("edge " << e << ", node " << i);
        CHECK(p * ijl.col(4 + e * (p - 1) + i - 1) ==
              (p - i) * corner[edges[e][0]] + i * corner[edges[e][1]]);
      }
    // Then each face (0,1,3), (2,3,1), (0,3,2), (0,2,1): a triangle of order
    // p - 3 in VTK order, shifted by (1, 1), on the face's corners.
    if (p >= 3) {
      const int faces[4][3] = {{0, 1, 3}, {2, 3, 1}, {0, 3, 2}, {0, 2, 1}};
      Eigen::Matrix2Xi ab = Eigen::Matrix2Xi::Zero(2, 1);
      if (p > 3) ab = vtk_triangle_node_indices(p - 3);
      ab.array() += 1;
      int k = 4 + 6 * (p - 1);
      for (const auto& f : faces)
        for (Eigen::Index m = 0; m < ab.cols(); ++m, ++k) {
          INFO("face node " << k);
          CHECK(p * ijl.col(k) == p * corner[f[0]] + ab(0, m) * (corner[f[1]] - corner[f[0]]) +
                                      ab(1, m) * (corner[f[2]] - corner[f[0]]));
        }
      // Then the interior, as a tetrahedron of order p - 4 shifted by (1, 1, 1).
      const Eigen::Index interior = n - k;
      CHECK(interior == (p - 3) * (p - 2) * (p - 1) / 6);
      if (p >= 5) {
        const Eigen::Matrix3Xi inner = vtk_tetrahedron_node_indices(p - 4);
        CHECK(ijl.rightCols(interior) == inner.colwise() + Eigen::Vector3i(1, 1, 1));
      } else if (p == 4) {
        CHECK(ijl.col(34) == Eigen::Vector3i(1, 1, 1));
      }
    }
    // Gmsh runs edges 0-3, 1-3, 2-3 the other way and lists them as 3-0, 3-2,
    // 3-1: from order 2 on the map is not the identity.
    if (p >= 2) CHECK(map != all);
  }
}

TEST_CASE("VTK Lagrange tetrahedra of order 1 and 2 are in VTK_TETRA and VTK_QUADRATIC_TETRA order",
          "[io][vtk_node_order]") {
  const auto rows = vtk_nodes();
  // VTK classic orders (vtkTetra, vtkQuadraticTetra): the corners, then for p = 2
  // the midpoints of edges 0-1, 1-2, 2-0, 0-3, 1-3, 2-3. Gmsh's 10-node
  // tetrahedron has edges 0-1, 1-2, 2-0, 3-0, 3-2, 3-1: its last two swap.
  CHECK(gmsh_to_vtk_tetrahedron(1) == std::vector<int>{0, 1, 2, 3});
  CHECK(gmsh_to_vtk_tetrahedron(2) == std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 9, 8});
  const Eigen::Matrix3Xi quadratic = vtk_tetrahedron_node_indices(2);
  const int edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  for (int e = 0; e < 6; ++e)
    CHECK(2 * quadratic.col(4 + e) == quadratic.col(edges[e][0]) + quadratic.col(edges[e][1]));
  // VTK's own classic cells, coordinate for coordinate.
  const std::vector<double>& tetra = rows.at({"Tetra", 1});
  const std::vector<double>& quadratic_tetra = rows.at({"QuadraticTetra", 2});
  CHECK(tetra == rows.at({"Tetrahedron", 1}));
  CHECK(quadratic_tetra == rows.at({"Tetrahedron", 2}));
  const Eigen::Matrix3Xi linear = vtk_tetrahedron_node_indices(1);
  REQUIRE(tetra.size() == 12);
  REQUIRE(quadratic_tetra.size() == 30);
  for (Eigen::Index k = 0; k < 4; ++k)
    for (int d = 0; d < 3; ++d) CHECK(linear(d, k) == tetra[3 * k + d]);
  for (Eigen::Index k = 0; k < 10; ++k)
    for (int d = 0; d < 3; ++d) CHECK(quadratic(d, k) * 0.5 == quadratic_tetra[3 * k + d]);
}
