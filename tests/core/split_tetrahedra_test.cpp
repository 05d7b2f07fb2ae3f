#include "core/split_tetrahedra.h"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <map>
#include <random>
#include <set>

#include "core/error.h"
#include "core/raise_volume_order.h"
#include "element/barycentric_indices.h"
#include "element/tet_lagrange_basis.h"
#include "two_tetrahedra.h"

using namespace homesh;

namespace {

// m's tetrahedron e mapped at reference point r.
Eigen::Vector3d map_at(const VolumeMesh& m, const TetLagrangeBasis& basis, int e,
                       const Eigen::Vector3d& r) {
  return m.tetrahedron_nodes(e) * basis.values(r);
}

}  // namespace

TEST_CASE("split_at_centroid children reproduce the curved parent exactly and share its faces",
          "[core][split_tetrahedra]") {
  for (int p = 1; p <= kMaxTetrahedronOrder; ++p) {
    INFO("p = " << p);
    VolumeMesh m = raise_volume_order(homesh::test::two_tetrahedra(), p);
    std::mt19937 rng(7 + p);
    std::uniform_real_distribution<double> jitter(-0.05, 0.05);
    for (int i = 5; i < m.num_nodes(); ++i)
      for (int d = 0; d < 3; ++d) m.x(d, i) += jitter(rng);
    const VolumeMesh before = m;
    const TetLagrangeBasis basis(p);

    REQUIRE(split_at_centroid(m, {0}) == std::vector<int>{0, 1, 0, 0, 0});
    REQUIRE(m.num_tetrahedra() == 5);
    CHECK(m.tet_entity == std::vector<int>(5, 1));
    // New nodes: the centroid, 4 edges, 6 faces and 4 child interiors, less
    // the parent's interior lattice nodes (reused).
    const int t3 = (p - 1) * (p - 2) * (p - 3) / 6;
    const int made = p == 1 ? 1 : 1 + 4 * (p - 1) + 3 * (p - 1) * (p - 2) + 4 * t3 - t3;
    CHECK(m.num_nodes() == before.num_nodes() + made);
    // Every node is used, new nodes lie inside the volume.
    std::set<int> used(m.tet.data(), m.tet.data() + m.tet.size());
    CHECK(static_cast<int>(used.size()) == m.num_nodes());
    for (int i = before.num_nodes(); i < m.num_nodes(); ++i) CHECK(m.node_class[i].dim == 3);
    // The neighbour is untouched.
    CHECK(m.tet.col(1) == before.tet.col(1));

    // Child f (column 0, then 2-4) replaces corner f by the parent's point at
    // the centroid M: its point r is the parent's at the barycentric mix, and
    // straight (p = 1) its volume is a quarter of the parent's.
    const Eigen::Matrix3Xd corners = before.tetrahedron_nodes(0).leftCols(4);
    const Eigen::Vector3d centroid = map_at(before, basis, 0, Eigen::Vector3d::Constant(0.25));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int column[4] = {0, 2, 3, 4};
    for (int f = 0; f < 4; ++f) {
      const int c = column[f];
      CHECK((m.x.col(m.tet(f, c)) - centroid).norm() < 1e-12);
      for (int trial = 0; trial < 5; ++trial) {
        Eigen::Vector4d l(unit(rng), unit(rng), unit(rng), unit(rng));
        l /= l.sum();
        Eigen::Vector4d parent_l = Eigen::Vector4d::Zero();
        for (int k = 0; k < 4; ++k)
          parent_l += l(k) * (k == f ? Eigen::Vector4d::Constant(0.25)
                                     : Eigen::Vector4d(Eigen::Vector4d::Unit(k)));
        const Eigen::Vector3d child = map_at(m, basis, c, l.tail<3>());
        const Eigen::Vector3d parent = map_at(before, basis, 0, parent_l.tail<3>());
        CHECK((child - parent).norm() < 1e-12);
      }
      Eigen::Matrix3d J, J0;
      const Eigen::Matrix3Xd X = m.tetrahedron_nodes(c);
      J << X.col(1) - X.col(0), X.col(2) - X.col(0), X.col(3) - X.col(0);
      J0 << corners.col(1) - corners.col(0), corners.col(2) - corners.col(0),
          corners.col(3) - corners.col(0);
      if (p == 1) CHECK(J.determinant() == Approx(J0.determinant() / 4).epsilon(1e-12));
    }
    // The parent's faces keep their nodes: child f's face opposite the centroid
    // is the parent's face opposite corner f, node for node.
    const Eigen::MatrixXi b = barycentric_indices(4, p);
    for (int f = 0; f < 4; ++f) {
      std::set<int> parent_face, child_face;
      for (Eigen::Index k = 0; k < b.cols(); ++k)
        if (b(f, k) == 0) {
          parent_face.insert(before.tet(k, 0));
          child_face.insert(m.tet(k, column[f]));
        }
      CHECK(parent_face == child_face);
    }
  }
}

TEST_CASE("wall_capped picks the flagged tetrahedra with four corners on the wall",
          "[core][split_tetrahedra]") {
  VolumeMesh m = homesh::test::two_tetrahedra();
  CHECK(wall_capped(m, {1, 1}).empty());
  m.node_class[3] = {2, 5};
  CHECK(wall_capped(m, {1, 1}) == std::vector<int>{0});
  CHECK(wall_capped(m, {0, 1}).empty());
  CHECK_THROWS_AS(split_at_centroid(m, {2}), Error);
  CHECK(split_at_centroid(m, {}) == std::vector<int>{0, 1});
}

TEST_CASE("split_edge halves every tetrahedron round the edge, exactly and conforming",
          "[core][split_tetrahedra]") {
  for (int p = 1; p <= kMaxTetrahedronOrder; ++p) {
    INFO("p = " << p);
    // Edge 1-2 is in both tetrahedra (corners 1, 2 of the first, 2, 0 of the second).
    VolumeMesh m = raise_volume_order(homesh::test::two_tetrahedra(), p);
    std::mt19937 rng(11 + p);
    std::uniform_real_distribution<double> jitter(-0.05, 0.05);
    for (int i = 5; i < m.num_nodes(); ++i)
      for (int d = 0; d < 3; ++d) m.x(d, i) += jitter(rng);
    const VolumeMesh before = m;
    const TetLagrangeBasis basis(p);

    REQUIRE(split_edge(m, 1, 2) == std::vector<int>{0, 1, 0, 1});
    REQUIRE(m.num_tetrahedra() == 4);
    std::set<int> used(m.tet.data(), m.tet.data() + m.tet.size());
    CHECK(static_cast<int>(used.size()) == m.num_nodes());
    for (int i = before.num_nodes(); i < m.num_nodes(); ++i) CHECK(m.node_class[i].dim == 3);

    // Parent e's corners ia, ib on the edge; its first child (column e) has the
    // midpoint M in place of ib, the second (column e + 2) in place of ia. A
    // child's point is the parent's at the mixed barycentric coordinates.
    const int ends[2][2] = {{1, 2}, {2, 0}};
    const Eigen::Vector3d mid =
        map_at(before, basis, 0, Eigen::Vector3d(0.5, 0.5, 0));  // corners 1, 2 of tet 0
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int e = 0; e < 2; ++e)
      for (int half = 0; half < 2; ++half) {
        const int c = e + 2 * half;
        const int moved = ends[e][half == 0 ? 1 : 0], kept = ends[e][half == 0 ? 0 : 1];
        CHECK((m.x.col(m.tet(moved, c)) - mid).norm() < 1e-12);
        for (int trial = 0; trial < 5; ++trial) {
          Eigen::Vector4d l(unit(rng), unit(rng), unit(rng), unit(rng));
          l /= l.sum();
          Eigen::Vector4d parent_l = l;
          parent_l(moved) = l(moved) / 2;
          parent_l(kept) += l(moved) / 2;
          const Eigen::Vector3d child = map_at(m, basis, c, l.tail<3>());
          const Eigen::Vector3d parent = map_at(before, basis, e, parent_l.tail<3>());
          CHECK((child - parent).norm() < 1e-12);
        }
        if (p == 1) {
          const auto volume = [](const Eigen::Matrix3Xd& X) {
            Eigen::Matrix3d J;
            J << X.col(1) - X.col(0), X.col(2) - X.col(0), X.col(3) - X.col(0);
            return J.determinant() / 6;
          };
          CHECK(volume(m.tetrahedron_nodes(c)) ==
                Approx(volume(before.tetrahedron_nodes(e)) / 2).epsilon(1e-12));
        }
      }
    // Conforming: every face two children share (the halves of each parent's
    // inner face, and the halves of the parents' shared face 1-2-3, whose
    // nodes the two parents' children make once) has the same nodes from
    // both sides.
    const Eigen::MatrixXi b = barycentric_indices(4, p);
    std::map<std::array<int, 3>, std::vector<std::set<int>>> faces;
    for (int c = 0; c < 4; ++c)
      for (int f = 0; f < 4; ++f) {
        std::array<int, 3> corners;
        std::set<int> nodes;
        for (int k = 0, n = 0; k < 4; ++k)
          if (k != f) corners[n++] = m.tet(k, c);
        std::sort(corners.begin(), corners.end());
        for (Eigen::Index k = 0; k < b.cols(); ++k)
          if (b(f, k) == 0) nodes.insert(m.tet(k, c));
        faces[corners].push_back(nodes);
      }
    int shared = 0;
    for (const auto& [corners, sides] : faces)
      if (sides.size() == 2) {
        ++shared;
        CHECK(sides[0] == sides[1]);
      }
    CHECK(shared == 4);
    CHECK(faces.size() == 12);
  }
}

TEST_CASE("split_edge refuses an edge no tetrahedron has", "[core][split_tetrahedra]") {
  VolumeMesh m = homesh::test::two_tetrahedra();
  CHECK_THROWS_WITH(split_edge(m, 0, 4), Catch::Contains("no tetrahedron has the edge"));
  CHECK_THROWS_AS(split_edge(m, 1, 1), Error);
  CHECK_THROWS_AS(split_edge(m, 1, 9), Error);
  CHECK(m.num_tetrahedra() == 2);
}
