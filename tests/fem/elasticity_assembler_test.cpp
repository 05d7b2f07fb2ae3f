// The repeated-assembly path (fixed pattern, coloured parallel loop, eliminated
// prescribed dofs) against the one-shot assemble_elasticity + apply_dirichlet,
// and the reuse of patterns and factorisations across solves.
#include "fem/elasticity_assembler.h"

#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <set>
#include <string>

#include "core/error.h"
#include "fem/solve_elasticity.h"
#include "fem_test_support.h"

using namespace homesh;
using namespace homesh::fem_test;

namespace {

struct Case {
  Mesh m;
  ElasticityCoefficients c;
  DirichletBC bc;
};

// A curved order-3 mesh with E varying in space, a body force and a thermal
// stress; whole nodes and single components prescribed, one node in no triangle.
Case test_case() {
  Case k{unit_square(3, 3), {}, {}};
  warp(k.m, 0.04);
  k.m.x.conservativeResize(2, k.m.num_nodes() + 1);
  k.m.x.col(k.m.num_nodes() - 1) << 3.0, 3.0;
  k.c.young = [](const QuadraturePoint& q) { return 1.0 + 4.0 * q.x(0) * q.x(1); };
  k.c.poisson = 0.3;
  k.c.body_force = Eigen::Vector2d(0.3, -1.0);
  k.c.beta = 0.2;
  k.c.temperature = [](const QuadraturePoint& q) { return q.x(0); };
  for (int i : square_boundary(k.m))
    if (k.m.x(0, i) < 1e-12) k.bc.fix(i, Eigen::Vector2d(0.05 * k.m.x(1, i), -0.02));
  k.bc.fix(5, 1, 0.01);
  k.bc.fix(k.m.num_nodes() - 1, 0, 0.5);
  return k;
}

Eigen::VectorXd prescribed_values(const DirichletBC& bc, int num_dofs) {
  Eigen::VectorXd g = Eigen::VectorXd::Zero(num_dofs);
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) g(bc.dofs[k]) = bc.values[k];
  return g;
}

}  // namespace

TEST_CASE("the fixed-pattern assembly equals assemble_elasticity + apply_dirichlet",
          "[fem][assembler]") {
  const Case k = test_case();
  LinearSystem reference = assemble_elasticity(k.m, k.c);
  apply_dirichlet(k.bc, reference);
  AssemblyOptions whole;  // the matrix compared entry by entry: no condensation
  whole.condense = false;
  const ElasticityAssembler assembler(k.m, k.bc.dofs, whole);
  EliminatedSystem sys;
  for (int pass = 0; pass < 2; ++pass) {  // the second refills the same pattern
    assembler.assemble(k.m.x, k.c, sys);
    const Eigen::MatrixXd K = sys.K, R = reference.K;
    const Eigen::MatrixXd lower = R.triangularView<Eigen::Lower>();
    CHECK((K - lower).cwiseAbs().maxCoeff() < 1e-13 * R.cwiseAbs().maxCoeff());
    const Eigen::VectorXd b = assembler.rhs(sys, prescribed_values(k.bc, assembler.num_dofs()));
    CHECK((b - reference.b).cwiseAbs().maxCoeff() < 1e-13 * reference.b.cwiseAbs().maxCoeff());
  }
  // The unused node: unit diagonal; its fixed x gets its value, its free y zero.
  const int last = 2 * (k.m.num_nodes() - 1);
  CHECK(sys.K.coeff(last, last) == 1.0);
  CHECK(sys.K.coeff(last + 1, last + 1) == 1.0);
}

TEST_CASE("colour classes partition the elements and share no node", "[fem][assembler]") {
  const Mesh m = unit_square(5, 2);
  const ElasticityAssembler assembler(m, {});
  std::set<int> seen;
  for (const std::vector<int>& colour : assembler.colours()) {
    std::set<int> nodes;
    for (int e : colour) {
      seen.insert(e);
      for (int i = 0; i < m.tri.rows(); ++i) CHECK(nodes.insert(m.tri(i, e)).second);
    }
  }
  CHECK(int(seen.size()) == m.num_triangles());
  // Each interior vertex of this mesh has 6 triangles: at least 6 colours.
  CHECK(assembler.colours().size() >= 6);
  CHECK(assembler.colours().size() <= 8);
}

TEST_CASE("ElasticitySolver reuses the analysis; resolve is linear in the prescribed values",
          "[fem][assembler]") {
  const Case k = test_case();
  for (const char* method : {"cholmod", "ldlt", "cg"}) {
    CAPTURE(method);
    ElasticityOptions options;
    options.solver.method = method;
    ElasticitySolver solver(k.m, k.bc, options);
    const Eigen::Matrix2Xd u = solver.solve(k.m.x, k.c, k.bc).u;
    CHECK((u - solve_elasticity(k.m, k.c, k.bc, options).u).cwiseAbs().maxCoeff() < 1e-9);
    // Loads off: the solution is linear in the prescribed values.
    ElasticityCoefficients elastic;
    elastic.poisson = 0.3;
    const Eigen::Matrix2Xd u1 = solver.solve(k.m.x, elastic, k.bc).u;
    DirichletBC twice = k.bc;
    for (double& v : twice.values) v *= 2.0;
    const Eigen::Matrix2Xd u2 = solver.resolve(twice).u;
    CHECK((u2 - 2.0 * u1).cwiseAbs().maxCoeff() < 1e-9 * u1.cwiseAbs().maxCoeff());
    // New positions, same pattern.
    Mesh moved = k.m;
    moved.x += 0.3 * u1;
    solver.solve(moved.x, elastic, k.bc);
    CHECK(solver.factorizations() == 3);
    CHECK(solver.analyses() == 1);
  }
  ElasticitySolver solver(k.m, k.bc);
  CHECK_THROWS_AS(solver.resolve(k.bc), Error);
  DirichletBC other = k.bc;
  const std::set<int> fixed(k.bc.dofs.begin(), k.bc.dofs.end());
  int free_dof = 0;
  while (fixed.count(free_dof)) ++free_dof;
  other.dofs.push_back(free_dof);
  other.values.push_back(0.0);
  CHECK_THROWS_AS(solver.solve(k.m.x, k.c, other), Error);
}

TEST_CASE("static condensation: the solution of the whole system with fewer dofs",
          "[fem][assembler][condense]") {
  for (int p = 2; p <= 5; ++p) {
    CAPTURE(p);
    Case k{unit_square(3, p), {}, {}};
    // The side x = 0 held (chosen on the straight mesh), the others traction free.
    for (int i : square_boundary(k.m))
      if (k.m.x(0, i) < 1e-12) k.bc.fix(i, Eigen::Vector2d(0.05 * k.m.x(1, i), -0.02));
    warp(k.m, 0.04);
    k.c.young = [](const QuadraturePoint& q) { return 1.0 + 4.0 * q.x(0) * q.x(1); };
    k.c.poisson = 0.45;
    k.c.body_force = Eigen::Vector2d(0.3, -1.0);
    k.c.beta = 0.2;
    k.c.temperature = [](const QuadraturePoint& q) { return q.x(0); };
    // One component of an interior node of the first triangle prescribed: that node
    // stays in the global system.
    const int interior = p >= 3 ? k.m.tri(triangle_node_count(p) - 1, 0) : -1;
    if (interior >= 0) k.bc.fix(interior, 1, 0.01);
    AssemblyOptions whole;
    whole.condense = false;
    const ElasticityAssembler condensed(k.m, k.bc.dofs), full(k.m, k.bc.dofs, whole);
    // The nodes in one triangle with both dofs free: (p - 1)(p - 2) / 2 interior nodes
    // per triangle less the one held, the p - 1 nodes of each of the 9 edges on the free
    // sides, and the corner (1, 0).
    const int interior_nodes = k.m.num_triangles() * (p - 1) * (p - 2) / 2;
    CHECK(condensed.num_condensed_dofs() ==
          2 * (interior_nodes - (interior >= 0 ? 1 : 0) + 9 * (p - 1) + 1));
    CHECK(full.num_condensed_dofs() == 0);
    EliminatedSystem a, b;
    condensed.assemble(k.m.x, k.c, a);
    full.assemble(k.m.x, k.c, b);
    if (p >= 3) CHECK(a.K.nonZeros() < b.K.nonZeros() * 3 / 4);
    for (const char* method : {"cholmod", "ldlt", "cg"}) {
      CAPTURE(method);
      ElasticityOptions with, without;
      with.solver.method = without.solver.method = method;
      without.assembly.condense = false;
      if (std::string(method) == "cg") with.solver.tolerance = without.solver.tolerance = 1e-13;
      ElasticitySolver s1(k.m, k.bc, with), s2(k.m, k.bc, without);
      const Eigen::Matrix2Xd u1 = s1.solve(k.m.x, k.c, k.bc).u;
      const Eigen::Matrix2Xd u2 = s2.solve(k.m.x, k.c, k.bc).u;
      const double scale = u2.cwiseAbs().maxCoeff();
      CHECK(scale > 0.01);
      CHECK((u1 - u2).cwiseAbs().maxCoeff() < 1e-9 * scale);
      // New prescribed values on the same factorisation: recovered from the same Z and z.
      DirichletBC other = k.bc;
      for (double& v : other.values) v *= -3.0;
      CHECK((s1.resolve(other).u - s2.resolve(other).u).cwiseAbs().maxCoeff() < 1e-9 * scale);
    }
  }
}
