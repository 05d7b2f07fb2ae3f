#include "core/raise_order.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <set>

#include "core/error.h"
#include "element/jacobian.h"
#include "element/lagrange_basis.h"
#include "element/quad_reference_nodes.h"
#include "element/reference_nodes.h"

using namespace homesh;

namespace {

// A fan of 3 linear triangles over a bottom curve (tag 1) with 2 inner nodes
// carrying curve parameters, closed by curves 2 and 3:
//
//            2
//          / | \            nodes: 0 (0,0), 1 (2,0), 2 (1.1,1.3) on model points;
//        /  /  \ \                 3 (0.8,0) u = 0.4, 4 (1.4,0) u = 0.7 on curve 1
//      0 -- 3 -- 4 -- 1     V = 5, E = 7, T = 3
//
// The line 4-3 runs against its triangle's edge 3-4.
Mesh fan() {
  Mesh m;
  m.order = 1;
  m.x.resize(2, 5);
  m.x << 0.0, 2.0, 1.1, 0.8, 1.4,  //
      0.0, 0.0, 1.3, 0.0, 0.0;
  m.node_class = {{0, 1}, {0, 2}, {0, 3}, {1, 1, 0.4}, {1, 1, 0.7}};
  m.tri.resize(3, 3);
  m.tri << 0, 3, 4,  //
      3, 4, 1,       //
      2, 2, 2;
  m.tri_entity = {7, 7, 7};
  m.line.resize(2, 5);
  m.line << 0, 4, 4, 1, 2,  //
      3, 3, 1, 2, 0;
  m.line_entity = {1, 1, 1, 2, 3};
  m.point_node = {0, 1, 2};
  m.point_entity = {1, 2, 3};
  m.entities = {{0, 1, {}}, {1, 1, {1, -2}}, {2, 7, {1, 2, 3}}};
  m.physicals = {{2, 5, "domain", {7}}};
  return m;
}

}  // namespace

TEST_CASE("raise_order node count is V + (p-1) E + (p-1)(p-2)/2 T", "[core][raise_order]") {
  const Mesh m = fan();
  for (int p = 1; p <= 8; ++p) {
    INFO("p = " << p);
    const Mesh r = raise_order(m, p);
    CHECK(r.order == p);
    CHECK(r.num_nodes() == 5 + (p - 1) * 7 + (p - 1) * (p - 2) / 2 * 3);
    CHECK(static_cast<int>(r.node_class.size()) == r.num_nodes());
    CHECK(r.tri.rows() == triangle_node_count(p));
    CHECK(r.line.rows() == p + 1);
    // Every node is used, corners keep their indices.
    std::set<int> used(r.tri.data(), r.tri.data() + r.tri.size());
    CHECK(static_cast<int>(used.size()) == r.num_nodes());
    CHECK(r.x.leftCols(5) == m.x);
    CHECK(r.tri.topRows(3) == m.tri);
    CHECK(r.line.topRows(2) == m.line);
    CHECK(r.point_node == m.point_node);
    CHECK(r.point_entity == m.point_entity);
    CHECK(r.physicals.size() == 1);
    CHECK(r.entities.size() == 3);
  }
}

TEST_CASE("raise_order shares edge nodes between triangles and with lines", "[core][raise_order]") {
  const Mesh m = fan();
  for (int p = 2; p <= 8; ++p) {
    INFO("p = " << p);
    const Mesh r = raise_order(m, p);
    auto edge_nodes = [&](int e, int k) {
      return r.tri.block(3 + k * (p - 1), e, p - 1, 1).col(0).eval();
    };
    // Edge 3-2: edge 1-2 of triangle 0 = (0, 3, 2) walks 3 -> 2, edge 2-0 of
    // triangle 1 = (3, 4, 2) walks 2 -> 3: the same nodes, reversed.
    CHECK(edge_nodes(0, 1) == edge_nodes(1, 2).reverse());
    // Edge 4-2: edge 1-2 of triangle 1 (4 -> 2), edge 2-0 of triangle 2 (2 -> 4).
    CHECK(edge_nodes(1, 1) == edge_nodes(2, 2).reverse());
    // Lines: 0-3 along edge 0-1 of triangle 0; 4-3 against edge 0-1 of
    // triangle 1; 4-1, 1-2 along triangle 2's edges 0-1 and 1-2; 2-0 against
    // triangle 0's edge 2-0 (walked 2 -> 0): same direction.
    CHECK(r.line.col(0).tail(p - 1) == edge_nodes(0, 0));
    CHECK(r.line.col(1).tail(p - 1) == edge_nodes(1, 0).reverse());
    CHECK(r.line.col(2).tail(p - 1) == edge_nodes(2, 0));
    CHECK(r.line.col(3).tail(p - 1) == edge_nodes(2, 1));
    CHECK(r.line.col(4).tail(p - 1) == edge_nodes(0, 2));
    // Line nodes sit at reference_line_nodes along the straight segment.
    const Eigen::RowVectorXd t = reference_line_nodes(p);
    for (int e = 0; e < r.num_lines(); ++e)
      for (int i = 0; i <= p; ++i) {
        const Eigen::Vector2d expected =
            (1.0 - t(i)) * r.x.col(r.line(0, e)) + t(i) * r.x.col(r.line(1, e));
        CHECK((r.x.col(r.line(i, e)) - expected).norm() < 1e-15);
      }
  }
}

TEST_CASE("raise_order keeps the linear Jacobian and places nodes affinely",
          "[core][raise_order]") {
  const Mesh m = fan();
  const Eigen::Matrix2Xd uv = reference_nodes(6) * 0.9 + Eigen::Matrix2Xd::Constant(2, 28, 0.03);
  for (int p = 1; p <= 8; ++p) {
    INFO("p = " << p);
    const Mesh r = raise_order(m, p);
    const LagrangeBasis basis(p);
    const Eigen::Matrix2Xd reference = reference_nodes(p);
    for (int e = 0; e < r.num_triangles(); ++e) {
      const Eigen::Matrix2Xd X = r.triangle_nodes(e);
      Eigen::Matrix2d A;
      A << X.col(1) - X.col(0), X.col(2) - X.col(0);
      const Eigen::Matrix2Xd affine = (A * reference).colwise() + X.col(0);
      CHECK((X - affine).cwiseAbs().maxCoeff() < 1e-14);
      for (Eigen::Index q = 0; q < uv.cols(); ++q)
        CHECK(jacobian(X, basis.gradients(uv.col(q))).determinant() ==
              Approx(A.determinant()).epsilon(1e-11));
    }
  }
}

TEST_CASE("raise_order classifies new nodes on curves and surfaces", "[core][raise_order]") {
  const Mesh m = fan();
  const int p = 4;
  const Mesh r = raise_order(m, p);
  const Eigen::RowVectorXd t = reference_line_nodes(p);
  auto check_line = [&](int line, int curve, double u0, double u1) {
    for (int i = 1; i < p; ++i) {
      const NodeClass& c = r.node_class[r.line(i + 1, line)];
      CHECK(c.dim == 1);
      CHECK(c.tag == curve);
      if (std::isnan(u0) || std::isnan(u1))
        CHECK(std::isnan(c.u));
      else
        CHECK(c.u == Approx((1.0 - t(i + 1)) * u0 + t(i + 1) * u1).epsilon(1e-15));
    }
  };
  const double nan = std::nan("");
  check_line(0, 1, nan, 0.4);  // node 0 is a model point without u
  check_line(1, 1, 0.7, 0.4);  // against the triangle's direction
  check_line(3, 2, nan, nan);
  // Interior edges and interior nodes are on surface 7.
  for (int e : {0, 1}) {
    for (int i = 0; i < p - 1; ++i) {
      const NodeClass& c = r.node_class[r.tri(3 + (p - 1) + i, e)];
      CHECK(c.dim == 2);
      CHECK(c.tag == 7);
      CHECK(std::isnan(c.u));
    }
  }
  for (int e = 0; e < r.num_triangles(); ++e)
    for (int i = 3 * p; i < r.tri.rows(); ++i) {
      CHECK(r.node_class[r.tri(i, e)].dim == 2);
      CHECK(r.node_class[r.tri(i, e)].tag == 7);
    }
  // Corners keep their classes.
  CHECK(r.node_class[3].u == 0.4);
  CHECK(r.node_class[0].dim == 0);
}

TEST_CASE("raise_order from a high-order mesh uses only its corners", "[core][raise_order]") {
  const Mesh m = fan();
  const Mesh direct = raise_order(m, 5);
  for (int q : {2, 3, 7}) {
    INFO("q = " << q);
    Mesh high = raise_order(m, q);
    // Curving the high-order nodes must not matter: only corners are read.
    high.x.rightCols(high.num_nodes() - 5).array() += 0.05;
    const Mesh r = raise_order(high, 5);
    CHECK(r.num_nodes() == direct.num_nodes());
    CHECK(r.tri == direct.tri);
    CHECK(r.line == direct.line);
    CHECK((r.x - direct.x).cwiseAbs().maxCoeff() < 1e-15);
    CHECK(r.point_node == direct.point_node);
  }
  const Mesh linear = raise_order(raise_order(m, 3), 1);
  CHECK(linear.x == m.x);
  CHECK(linear.tri == m.tri);
  CHECK(linear.line == m.line);
}

TEST_CASE("raise_order rejects orders outside 1..10", "[core][raise_order]") {
  const Mesh m = fan();
  CHECK_NOTHROW(raise_order(m, 10));
  CHECK_THROWS_AS(raise_order(m, 0), Error);
  CHECK_THROWS_WITH(raise_order(m, 11), Catch::Contains("order 11"));
}

TEST_CASE("raise_order raises quadrilaterals beside triangles, sharing their edge nodes",
          "[core][raise_order][quad]") {
  // A quadrilateral 0 1 2 3 (a trapezium, so the bilinear map is not affine) and a
  // triangle 1 4 2 on its edge 1-2; lines 0-1 (curve 1, u from 0 to 1) and 4-2.
  Mesh m;
  m.order = 1;
  m.x.resize(2, 5);
  m.x << 0.0, 1.0, 0.8, 0.0, 2.0,  //
      0.0, 0.0, 1.0, 1.0, 0.5;
  m.node_class = {{0, 1, 0.0}, {0, 2, 1.0}, {2, 7}, {2, 7}, {2, 7}};
  m.tri.resize(3, 1);
  m.tri << 1, 4, 2;
  m.tri_entity = {7};
  m.quad.resize(4, 1);
  m.quad << 0, 1, 2, 3;
  m.quad_entity = {7};
  m.line.resize(2, 2);
  m.line << 0, 4,  //
      1, 2;
  m.line_entity = {1, 2};
  m.entities = {{1, 1, {}}, {1, 2, {}}, {2, 7, {1, 2}}};
  for (int p = 1; p <= 6; ++p) {
    INFO("p = " << p);
    const Mesh r = raise_order(m, p);
    // V + (p-1) E + (p-1)(p-2)/2 T + (p-1)^2 Q with V = 5, E = 6 (4 quad edges, 2 more).
    CHECK(r.num_nodes() == 5 + (p - 1) * 6 + (p - 1) * (p - 2) / 2 + (p - 1) * (p - 1));
    REQUIRE(r.quad.rows() == quad_node_count(p));
    CHECK(r.quad_entity == m.quad_entity);
    CHECK(r.quad.topRows(4) == m.quad);
    // Quad edge 1-2 (its edge k = 1, walked 1 -> 2) is the triangle's edge 2-0
    // (walked 2 -> 1): the same nodes, reversed.
    const Eigen::VectorXi quad_edge = r.quad.block(4 + (p - 1), 0, p - 1, 1);
    const Eigen::VectorXi tri_edge = r.tri.block(3 + 2 * (p - 1), 0, p - 1, 1);
    CHECK(quad_edge == tri_edge.reverse());
    // Line 0-1 is quad edge 0, with its curve parameter interpolated.
    CHECK(r.line.col(0).tail(p - 1) == r.quad.block(4, 0, p - 1, 1));
    for (int i = 2; i <= p; ++i) {
      CHECK(r.node_class[r.line(i, 0)].dim == 1);
      CHECK(r.node_class[r.line(i, 0)].u == Approx(r.x(0, r.line(i, 0))).margin(1e-15));
    }
    // Every quad node sits at the bilinear image of its reference node.
    const Eigen::Matrix2Xd uv = quad_reference_nodes(p);
    for (int k = 0; k < quad_node_count(p); ++k) {
      const double u = uv(0, k), v = uv(1, k);
      const Eigen::Vector2d expected = (1 - u) * (1 - v) * m.x.col(0) + u * (1 - v) * m.x.col(1) +
                                       u * v * m.x.col(2) + (1 - u) * v * m.x.col(3);
      CHECK((r.x.col(r.quad(k, 0)) - expected).norm() < 1e-14);
      if (k >= 4) CHECK(r.node_class[r.quad(k, 0)].dim >= 1);
    }
    // Every node is used once at least, by the quad, the triangle or a line.
    std::set<int> used(r.tri.data(), r.tri.data() + r.tri.size());
    used.insert(r.quad.data(), r.quad.data() + r.quad.size());
    CHECK(static_cast<int>(used.size()) == r.num_nodes());
  }
  // Raised back to p = 1 from p = 4, only the corners remain.
  const Mesh back = raise_order(raise_order(m, 4), 1);
  CHECK(back.num_nodes() == 5);
  CHECK(back.quad == m.quad);
}
