// Optimal interior elements (thesis Section 3.8.2): every measure's distortion
// function is 0 at the equilateral element, and PRAXIS and the brute-force
// grid both bring the free node back there (Tables 3.3-3.5: "all measures have
// displayed good high-order mesh guidance for interior regions").
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.h"
#include "optim/ideal_element.h"
#include "optim/interior_optimum.h"
#include "quality/jacobian_bounds.h"

using namespace homesh;

TEST_CASE("the equilateral element has W = I at every node", "[optim]") {
  const Eigen::Matrix2Xd X = equilateral_element(3);
  REQUIRE(X.cols() == 10);
  CHECK((X.col(2) - Eigen::Vector2d(0.5, std::sqrt(3.0) / 2)).norm() < 1e-15);
  CHECK((X.col(9) - Eigen::Vector2d(0.5, std::sqrt(3.0) / 6)).norm() < 1e-15);
  CHECK((X.col(3) - Eigen::Vector2d(1.0 / 3, 0)).norm() < 1e-15);
}

TEST_CASE("free-node distortion: 0 at the ideal, the start's f, node bookkeeping", "[optim]") {
  const OptimisationCase c = quadratic_interior_case();
  for (const Measure& m : measures()) {
    INFO(m.name);
    const FreeNodeDistortion f(m, c.start, c.order, c.free_nodes);
    CHECK(f.dimension() == 2);
    CHECK(f.start() == Eigen::Vector2d(0.7225, -0.2225));
    CHECK(f(Eigen::Vector2d(0.5, 0.0)) < 1e-12);
    CHECK(f(f.start()) > 0.05);
    CHECK((f.element(f.start()) - c.start).norm() == 0.0);
  }
  CHECK_THROWS_AS(FreeNodeDistortion(measure("Q2"), c.start, 2, {6}), Error);
  CHECK_THROWS_AS(FreeNodeDistortion(measure("Q2"), c.start, 3, {3}), Error);
}

TEST_CASE("the interior cases start where Q2 has the thesis's f0 = 1.0, valid", "[optim]") {
  for (const OptimisationCase& c : {quadratic_interior_case(), cubic_interior_case()}) {
    INFO(c.name);
    const FreeNodeDistortion f(measure("Q2"), c.start, c.order, c.free_nodes);
    CHECK(f(f.start()) == Approx(1.0).margin(1e-3));
    CHECK(jacobian_bounds(c.start, c.order).valid_certified);
  }
}

TEST_CASE("PRAXIS and brute force reach the equilateral element for every measure", "[optim]") {
  InteriorSearch search;
  search.grid = {41, 3};
  for (const OptimisationCase& c : {quadratic_interior_case(), cubic_interior_case()}) {
    for (const Measure& m : measures()) {
      INFO(c.name << " " << m.name);
      const InteriorOptimum r = find_interior_optimum(m, c, search);
      CHECK(r.praxis_error < 1e-3);
      CHECK(r.grid_error < 1e-3);
      CHECK(r.praxis.f < 1e-3);
      CHECK(r.praxis.f < r.praxis.f0);
      // Same order of magnitude as the thesis's 146-692 evaluations.
      CHECK(r.praxis.evaluations > 20);
      CHECK(r.praxis.evaluations < 1000);
    }
  }
}
