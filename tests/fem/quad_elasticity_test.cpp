// The elastic analogy on quadrilaterals and on meshes mixing them with
// triangles: the quad tabulation, the patch test, h-convergence, and the
// assembler's mixed connectivity (kernel, colouring, error messages).
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <set>
#include <string>

#include "core/error.h"
#include "fem/element_load.h"
#include "fem/element_stiffness.h"
#include "fem/solve_elasticity.h"
#include "fem_test_support.h"

using namespace homesh;
using namespace homesh::fem_test;

namespace {

// The 2 #nodes interleaved vectors of the three rigid motions at x.
Eigen::MatrixXd rigid_motions(const Eigen::Matrix2Xd& x) {
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(2 * x.cols(), 3);
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    R(2 * i, 0) = 1;
    R(2 * i + 1, 1) = 1;
    R(2 * i, 2) = -x(1, i);
    R(2 * i + 1, 2) = x(0, i);
  }
  return R;
}

}  // namespace

TEST_CASE("tabulate_quad_element: a partition of unity on a rule of degree 2p + margin",
          "[fem][quad]") {
  for (int p = 1; p <= 10; ++p) {
    INFO("p = " << p);
    const ElementTabulation tab = tabulate_quad_element(p, quad_stiffness_quadrature_degree(p, 2));
    CHECK(tab.quad);
    CHECK(tab.N.rows() == quad_node_count(p));
    CHECK(tab.rule.points.cols() == (p + 2) * (p + 2));
    CHECK(tab.rule.weights.sum() == Approx(1.0).epsilon(1e-14));
    CHECK((tab.N.colwise().sum().array() - 1.0).abs().maxCoeff() < 1e-10);
    CHECK(tab.dNdu.colwise().sum().cwiseAbs().maxCoeff() < 1e-8);
    CHECK(tab.dNdv.colwise().sum().cwiseAbs().maxCoeff() < 1e-8);
  }
  CHECK_THROWS_AS(quad_stiffness_quadrature_degree(2, -1), Error);
}

TEST_CASE("quad stiffness: exact at degree 2p on a parallelogram, rigid motions in its kernel",
          "[fem][quad]") {
  // A parallelogram (J constant) with its high-order nodes where the affine
  // map puts them: margin 0 and margin 6 agree (degree 2p per variable is
  // exact), one degree less does not.
  Eigen::Matrix2d A;
  A << 1.3, 0.4, -0.2, 0.9;
  const Eigen::Vector2d origin(0.5, -0.3);
  for (int p = 1; p <= 6; ++p) {
    INFO("p = " << p);
    const Eigen::Matrix2Xd X = (A * quad_reference_nodes(p)).colwise() + origin;
    auto stiffness = [&](int degree) {
      const ElementTabulation tab = tabulate_quad_element(p, degree);
      const Eigen::Index nq = tab.rule.points.cols();
      return element_stiffness(X, tab, Eigen::VectorXd::Constant(nq, 1.1),
                               Eigen::VectorXd::Constant(nq, 0.7));
    };
    const Eigen::MatrixXd K = stiffness(quad_stiffness_quadrature_degree(p, 0));
    const Eigen::MatrixXd fine = stiffness(quad_stiffness_quadrature_degree(p, 6));
    const Eigen::MatrixXd coarse = stiffness(2 * p - 2);  // floor(d / 2) + 1 = p points
    CHECK((K - fine).cwiseAbs().maxCoeff() < 1e-12 * fine.cwiseAbs().maxCoeff());
    CHECK((coarse - fine).cwiseAbs().maxCoeff() > 1e-6 * fine.cwiseAbs().maxCoeff());
    CHECK((K - K.transpose()).cwiseAbs().maxCoeff() == 0.0);
    // Rigid motions, dofs [u_1 .. u_n, v_1 .. v_n].
    const Eigen::Index n = X.cols();
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(2 * n, 3);
    R.col(0).head(n).setOnes();
    R.col(1).tail(n).setOnes();
    R.col(2).head(n) = -X.row(1).transpose();
    R.col(2).tail(n) = X.row(0).transpose();
    CHECK((K * R).cwiseAbs().maxCoeff() < 1e-11 * K.cwiseAbs().maxCoeff());
    // Exactly three zero eigenvalues: the quad has no spurious modes.
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
    CHECK(ev(2) < 1e-10 * ev(2 * n - 1));
    CHECK(ev(3) > 1e-6 * ev(2 * n - 1));
  }
}

TEST_CASE(
    "mixed patch test: an affine boundary displacement is reproduced at every node, p = 1..10",
    "[fem][quad][patch]") {
  for (int p : {1, 2, 3, 4, 6, 10}) {
    for (double curve : {0.0, 0.04}) {
      INFO("p = " << p << ", curve = " << curve);
      Mesh m = mixed_square(3, p, 2);
      REQUIRE(m.num_triangles() == 6);
      REQUIRE(m.num_quads() == 6);
      const std::vector<int> boundary = square_boundary(m);
      warp(m, curve);
      DirichletBC bc;
      for (int i : boundary) bc.fix(i, patch_field(m.x.col(i)));
      ElasticityCoefficients c;
      c.poisson = 0.45;
      c.young = 2.0;
      const ElasticitySolution s = solve_elasticity(m, c, bc);
      CHECK((s.u - interpolate(m, patch_field)).cwiseAbs().maxCoeff() < 1e-10);
    }
  }
  // Quadrilaterals alone, the triangle matrix left empty (0 by 0).
  Mesh m = mixed_square(2, 3, 2);
  m.tri.resize(0, 0);
  m.tri_entity.clear();
  warp(m, 0.04);
  DirichletBC bc;
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_class[i].dim < 2) bc.fix(i, patch_field(m.x.col(i)));
  const ElasticitySolution s = solve_elasticity(m, ElasticityCoefficients{}, bc);
  CHECK((s.u - interpolate(m, patch_field)).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("quads and mixed meshes: L2 error at rate p + 1, energy error at rate p, p = 1..3",
          "[fem][quad][convergence]") {
  const Lame l = lame_plane_strain(1.0, 0.3);
  ElasticityCoefficients c;
  c.poisson = 0.3;
  c.body_force = [&l](const QuadraturePoint& q) { return manufactured_body_force(l, q.x); };
  for (int p = 1; p <= 3; ++p) {
    for (const bool all_quads : {true, false}) {
      ErrorNorms previous;
      for (int n : {4, 8}) {
        Mesh m = mixed_square(n, p, all_quads ? n : n / 2);
        REQUIRE(m.num_quads() == (all_quads ? n * n : n * n / 2));
        DirichletBC bc;
        for (int i : square_boundary(m)) bc.fix(i, manufactured_exact(m.x.col(i)));
        const ElasticitySolution s = solve_elasticity(m, c, bc);
        const ErrorNorms e =
            error_norms(m, s.u, manufactured_exact, manufactured_gradient, l.lambda, l.mu);
        if (n == 8) {
          INFO("p = " << p << (all_quads ? ", quads" : ", mixed") << ": L2 " << previous.l2
                      << " -> " << e.l2 << ", energy " << previous.energy << " -> " << e.energy);
          CHECK(std::log2(previous.l2 / e.l2) == Approx(p + 1).margin(0.3));
          CHECK(std::log2(previous.energy / e.energy) == Approx(p).margin(0.3));
        }
        previous = e;
      }
    }
  }
}

TEST_CASE("quads against triangles: the two solutions on one domain agree as h -> 0",
          "[fem][quad][convergence]") {
  // The same problem on n by n quads and on the same cells cut into
  // triangles (same nodes at p = 2: a cell's 9 nodes); the difference at the
  // nodes falls at rate >= p + 1 = 3.
  const Lame l = lame_plane_strain(1.0, 0.3);
  ElasticityCoefficients c;
  c.poisson = 0.3;
  c.body_force = [&l](const QuadraturePoint& q) { return manufactured_body_force(l, q.x); };
  double previous = 0;
  for (int n : {4, 8}) {
    const Mesh quads = mixed_square(n, 2, n), triangles = mixed_square(n, 2, 0);
    REQUIRE(quads.num_nodes() == triangles.num_nodes());
    REQUIRE((quads.x - triangles.x).cwiseAbs().maxCoeff() == 0.0);
    DirichletBC bc;
    for (int i : square_boundary(quads)) bc.fix(i, manufactured_exact(quads.x.col(i)));
    const double difference =
        (solve_elasticity(quads, c, bc).u - solve_elasticity(triangles, c, bc).u)
            .cwiseAbs()
            .maxCoeff();
    if (n == 8) {
      INFO("max nodal difference " << previous << " -> " << difference);
      CHECK(difference < 1e-3);
      CHECK(std::log2(previous / difference) > 2.7);
    }
    previous = difference;
  }
}

TEST_CASE(
    "mixed assembly: rigid motions in the kernel, colours share no node, errors name the quad",
    "[fem][quad][assembler]") {
  Mesh m = mixed_square(4, 3, 2);
  warp(m, 0.04);
  const LinearSystem sys = assemble_elasticity(m, ElasticityCoefficients{});
  const Eigen::MatrixXd R = rigid_motions(m.x);
  CHECK((sys.K * R).cwiseAbs().maxCoeff() < 1e-11 * sys.K.coeffs().cwiseAbs().maxCoeff());
  // Every dof of every element is in the pattern: a quad's opposite corners couple.
  const int a = m.quad(0, 0), b = m.quad(2, 0);
  CHECK(sys.K.coeff(2 * a, 2 * b) != 0.0);

  const ElasticityAssembler assembler(m, {});
  std::set<int> seen;
  for (const std::vector<int>& colour : assembler.colours()) {
    std::set<int> nodes;
    for (int e : colour) {
      CHECK(seen.insert(e).second);
      const bool quad = e >= m.num_triangles();
      const Eigen::VectorXi col =
          quad ? Eigen::VectorXi(m.quad.col(e - m.num_triangles())) : Eigen::VectorXi(m.tri.col(e));
      for (Eigen::Index i = 0; i < col.size(); ++i) CHECK(nodes.insert(col(i)).second);
    }
  }
  CHECK(int(seen.size()) == m.num_elements_2d());

  // An interior node of quadrilateral 3 (its own) thrown out of it: det J
  // changes sign there, and the message names it by its index.
  Mesh bad = m;
  bad.x(0, bad.quad(12, 3)) += 1.0;
  try {
    assemble_elasticity(bad, ElasticityCoefficients{});
    FAIL("no error");
  } catch (const Error& e) {
    CHECK_THAT(e.what(), Catch::Contains("quadrilateral 3 (2D element " +
                                         std::to_string(m.num_triangles() + 3) + ")"));
  }
  Mesh wrong = m;
  wrong.quad.conservativeResize(9, Eigen::NoChange);
  CHECK_THROWS_WITH(assemble_elasticity(wrong, ElasticityCoefficients{}),
                    Catch::Contains("9 nodes per quadrilateral for order 3"));
}

TEST_CASE("mixed assembly: the dense sum of the element matrices, and the eliminated system",
          "[fem][quad][assembler]") {
  Mesh m = mixed_square(3, 2, 1);
  warp(m, 0.04);
  ElasticityCoefficients c;
  c.young = [](const QuadraturePoint& q) { return 1.0 + q.x(0) + 0.1 * q.element; };
  c.poisson = 0.35;
  c.body_force = Eigen::Vector2d(0.3, -1.0);
  // K and b by hand: each element's Ke and fe (dofs [u_1 .. u_n, v_1 .. v_n])
  // added at the interleaved global dofs.
  const int N = 2 * m.num_nodes();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(N, N);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(N);
  const ElementTabulation tri_tab = tabulate_element(2, stiffness_quadrature_degree(2, 2));
  const ElementTabulation quad_tab =
      tabulate_quad_element(2, quad_stiffness_quadrature_degree(2, 2));
  for (int e = 0; e < m.num_elements_2d(); ++e) {
    const bool quad = e >= m.num_triangles();
    const int local = quad ? e - m.num_triangles() : e;
    const ElementTabulation& tab = quad ? quad_tab : tri_tab;
    const Eigen::VectorXi nodes =
        quad ? Eigen::VectorXi(m.quad.col(local)) : Eigen::VectorXi(m.tri.col(local));
    const ElementGeometry g =
        element_geometry(quad ? m.quad_nodes(local) : m.triangle_nodes(local), tab);
    const Eigen::Index nq = g.x.cols(), n = nodes.size();
    Eigen::VectorXd lambda(nq), mu(nq);
    for (Eigen::Index q = 0; q < nq; ++q) {
      const QuadraturePoint point{e, int(q), g.x.col(q)};
      const Lame l = lame_plane_strain(c.young(point), c.poisson(point));
      lambda(q) = l.lambda;
      mu(q) = l.mu;
    }
    const Eigen::MatrixXd Ke = element_stiffness(g, lambda, mu);
    const Eigen::VectorXd fe =
        element_load(g, tab.N, Eigen::Matrix2Xd(Eigen::Vector2d(0.3, -1.0).replicate(1, nq)),
                     Eigen::Matrix3Xd::Zero(3, nq));
    for (Eigen::Index a = 0; a < 2 * n; ++a) {
      const int row = 2 * nodes(a % n) + int(a / n);
      b(row) += fe(a);
      for (Eigen::Index k = 0; k < 2 * n; ++k) K(row, 2 * nodes(k % n) + int(k / n)) += Ke(a, k);
    }
  }
  const LinearSystem sys = assemble_elasticity(m, c);
  const Eigen::MatrixXd assembled = sys.K;
  CHECK((assembled - K).cwiseAbs().maxCoeff() < 1e-13 * K.cwiseAbs().maxCoeff());
  CHECK((sys.b - b).cwiseAbs().maxCoeff() < 1e-13 * b.cwiseAbs().maxCoeff());

  // The eliminated system of the repeated assembly against apply_dirichlet.
  DirichletBC bc;
  for (int i : square_boundary(m))
    if (m.x(0, i) < 0.01) bc.fix(i, Eigen::Vector2d(0.05 * m.x(1, i), -0.02));
  bc.fix(m.quad(8, 1), 1, 0.01);  // one component of a quad's interior node
  LinearSystem reference = sys;
  apply_dirichlet(bc, reference);
  AssemblyOptions whole;  // the matrix compared entry by entry: no condensation
  whole.condense = false;
  const ElasticityAssembler assembler(m, bc.dofs, whole);
  EliminatedSystem eliminated;
  assembler.assemble(m.x, c, eliminated);
  const Eigen::MatrixXd lower = Eigen::MatrixXd(reference.K).triangularView<Eigen::Lower>();
  CHECK((Eigen::MatrixXd(eliminated.K) - lower).cwiseAbs().maxCoeff() <
        1e-13 * lower.cwiseAbs().maxCoeff());
  Eigen::VectorXd g = Eigen::VectorXd::Zero(N);
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) g(bc.dofs[k]) = bc.values[k];
  CHECK((assembler.rhs(eliminated, g) - reference.b).cwiseAbs().maxCoeff() <
        1e-13 * reference.b.cwiseAbs().maxCoeff());

  // Condensed: the nodes in one element with neither dof held (the quadrilaterals'
  // interior nodes but the one held, and edge nodes and corners of the free sides).
  // The same solution.
  const ElasticityAssembler condensing(m, bc.dofs);
  std::vector<int> elements_of(m.num_nodes(), 0);
  for (int e = 0; e < m.num_elements_2d(); ++e)
    for (const int node : element_node_indices(m, e)) ++elements_of[node];
  const std::set<int> held(bc.dofs.begin(), bc.dofs.end());
  int alone = 0, interior = 0;
  for (int i = 0; i < m.num_nodes(); ++i)
    alone += elements_of[i] == 1 && !held.count(2 * i) && !held.count(2 * i + 1);
  for (int q = 0; q < m.num_quads(); ++q) interior += !held.count(2 * m.quad(8, q) + 1);
  CHECK(interior == m.num_quads() - 1);
  CHECK(alone > interior);
  CHECK(condensing.num_condensed_dofs() == 2 * alone);
  ElasticityOptions without;
  without.assembly.condense = false;
  const Eigen::Matrix2Xd u1 = solve_elasticity(m, c, bc).u;
  const Eigen::Matrix2Xd u2 = solve_elasticity(m, c, bc, without).u;
  CHECK(u2.cwiseAbs().maxCoeff() > 0.01);
  CHECK((u1 - u2).cwiseAbs().maxCoeff() < 1e-10 * u2.cwiseAbs().maxCoeff());
}
