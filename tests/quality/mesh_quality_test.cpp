#include "quality/mesh_quality.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "../fem/fem_test_support.h"
#include "element/quad_reference_nodes.h"
#include "element/reference_nodes.h"
#include "quality/mesh_validity.h"

using namespace homesh;

TEST_CASE("mesh_measures agrees with element_quality, whatever the lattice", "[quality]") {
  Mesh m = fem_test::unit_square(3, 3);
  fem_test::warp(m, 0.05);
  std::vector<const Measure*> qs;
  for (const char* name : {"Q1", "Q4", "Q11", "Q17"}) qs.push_back(&measure(name));
  for (int lattice : {6, 7}) {  // a multiple of p = 3 (nodes on it), and not
    CAPTURE(lattice);
    const auto results = mesh_measures(m, qs, lattice, Reference::element_max);
    Eigen::Matrix2Xd uv(2, reference_nodes(lattice).cols() + 10);
    uv << reference_nodes(lattice), reference_nodes(3);
    for (std::size_t j = 0; j < qs.size(); ++j) {
      for (int e = 0; e < m.num_triangles(); ++e) {
        const ElementQuality ref =
            element_quality(*qs[j], m.triangle_nodes(e), 3, uv, Reference::element_max);
        REQUIRE(results[j].element_min(e) == Approx(ref.min).epsilon(1e-12));
        for (int i = 0; i < 10; ++i)
          REQUIRE(results[j].node_values(i, e) ==
                  Approx(ref.values(uv.cols() - 10 + i)).epsilon(1e-12));
      }
    }
  }
}

TEST_CASE("mesh_validity counts the invalid triangles and finds the worst", "[quality]") {
  Mesh m = fem_test::unit_square(2, 2);
  REQUIRE(mesh_validity(m).invalid == 0);
  REQUIRE(mesh_validity(m).worst == Approx(1.0));
  // Push the mid-node of one diagonal edge across the triangle beside it.
  int moved = -1;
  for (int i = 0; i < m.num_nodes(); ++i)
    if (std::abs(m.x(0, i) - 0.25) < 1e-12 && std::abs(m.x(1, i) - 0.25) < 1e-12) moved = i;
  REQUIRE(moved >= 0);
  m.x(0, moved) += 0.4;
  const MeshValidity v = mesh_validity(m);
  REQUIRE(v.invalid == 1);  // the triangle it is pushed into (the other bulges out)
  REQUIRE(v.worst < 0);
  REQUIRE(v.ratio(v.worst_element) == v.worst);
  REQUIRE(v.ratio.minCoeff() == v.worst);
}

TEST_CASE("mesh_quality is mesh_validity and mesh_measures in one pass", "[quality]") {
  Mesh m = fem_test::unit_square(3, 4);
  fem_test::warp(m, 0.08);
  // One triangle made invalid: an interior node of the first pushed outside it.
  m.x.col(m.tri(12, 0)) += Eigen::Vector2d(0.4, -0.3);
  std::vector<const Measure*> qs;
  for (const char* name : {"Q1", "Q4", "Q11", "Q17"}) qs.push_back(&measure(name));
  BoundsOptions opt;
  opt.relative_tolerance = 1e-4;
  const MeshQuality both = mesh_quality(m, qs, 8, Reference::element_max, opt);
  const MeshValidity alone = mesh_validity(m, opt);
  REQUIRE(alone.invalid >= 1);
  CHECK(both.validity.invalid == alone.invalid);
  CHECK(both.validity.worst_element == alone.worst_element);
  CHECK(both.validity.relative_tolerance == 1e-4);
  CHECK((both.validity.ratio - alone.ratio).cwiseAbs().maxCoeff() == 0.0);
  CHECK((both.validity.min_det - alone.min_det).cwiseAbs().maxCoeff() == 0.0);
  const auto measures = mesh_measures(m, qs, 8, Reference::element_max);
  REQUIRE(both.measures.size() == qs.size());
  for (std::size_t j = 0; j < qs.size(); ++j) {
    CHECK((both.measures[j].element_min - measures[j].element_min).cwiseAbs().maxCoeff() == 0.0);
    CHECK((both.measures[j].node_values - measures[j].node_values).cwiseAbs().maxCoeff() == 0.0);
  }
  // The invalid triangle scores 0 in every measure that needs omega > 0.
  const int bad = alone.worst_element;
  for (std::size_t j = 1; j < qs.size(); ++j) CHECK(both.measures[j].element_min(bad) == 0.0);
}

TEST_CASE("measures on quadrilaterals: 1 at the unit square, analytic on a 2:1 rectangle",
          "[quality][mesh_quality][quads]") {
  for (int p = 1; p <= 3; ++p) {
    INFO("p = " << p);
    // The unit square, and a 2:1 rectangle beside it; one triangle below.
    const Eigen::Matrix2Xd ref = quad_reference_nodes(p);
    const int n = static_cast<int>(ref.cols());
    Mesh m;
    m.order = p;
    m.x.resize(2, 2 * n + triangle_node_count(p));
    m.x.leftCols(n) = ref;
    m.x.middleCols(n, n) = Eigen::Vector2d(2.0, 1.0).asDiagonal() * ref;
    m.x.middleCols(n, n).row(0).array() += 2.0;
    m.x.rightCols(triangle_node_count(p)) = reference_nodes(p);
    m.x.rightCols(triangle_node_count(p)).row(1).array() -= 1.0;
    m.quad.resize(n, 2);
    for (int k = 0; k < n; ++k) m.quad.col(0)(k) = k, m.quad.col(1)(k) = n + k;
    m.quad_entity = {1, 1};
    m.tri.resize(triangle_node_count(p), 1);
    for (int k = 0; k < triangle_node_count(p); ++k) m.tri(k, 0) = 2 * n + k;
    m.tri_entity = {1};
    std::vector<const Measure*> qs;
    for (const Measure& q : measures()) qs.push_back(&q);
    const MeshQuality r = mesh_quality(m, qs, default_lattice_order(p), Reference::ideal);
    REQUIRE(r.validity.ratio.size() == 3);
    CHECK(r.validity.invalid == 0);
    CHECK(r.validity.ratio(1) == Approx(1.0));  // straight-sided: det J constant
    CHECK(r.validity.min_det(1) == Approx(1.0));
    CHECK(r.validity.min_det(2) == Approx(2.0));
    for (std::size_t j = 0; j < qs.size(); ++j) {
      INFO(qs[j]->name);
      const MeshMeasure& q = r.measures[j];
      REQUIRE(q.element_min.size() == 3);
      REQUIRE(q.node_values.rows() == n);
      CHECK(q.element_min(1) == Approx(1.0));
      CHECK(q.node_values.col(1).minCoeff() == Approx(1.0));
      CHECK(q.node_values.col(2).maxCoeff() == Approx(q.element_min(2)));
    }
    // W = diag(2, 1): Q7 = 2 omega / |W|_F^2 = 4 / 5, Q17 = min(omega, 1/omega) = 1/2.
    CHECK(r.measures[6].element_min(2) == Approx(0.8));
    CHECK(r.measures[15].element_min(2) == Approx(0.5));
  }
}
