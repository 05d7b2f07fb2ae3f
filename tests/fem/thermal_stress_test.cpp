// Thermal stresses (Eq 4.5 and the anisotropic term of Sec 4.4.1): a uniform
// thermal stress on a free body gives a uniform strain eps = -C^-1 sigma_t,
// with C the plane-strain elasticity tensor.
#include <catch2/catch.hpp>

#include "fem/solve_elasticity.h"
#include "fem_test_support.h"

using namespace homesh;
using namespace homesh::fem_test;

namespace {

// Corner nodes of the unit square mesh at (0,0) and (1,0) (before perturbation).
int node_at(const Mesh& m, const Eigen::Vector2d& x) {
  for (int i = 0; i < m.num_nodes(); ++i)
    if ((m.x.col(i) - x).norm() < 1e-12) return i;
  return -1;
}

// The plane-strain strain of a stress S: eps = (S - lambda tr(S) / (2 (lambda + mu)) I) / (2 mu).
Eigen::Matrix2d compliance(const Lame& l, const Eigen::Matrix2d& S) {
  return (S - l.lambda * S.trace() / (2.0 * (l.lambda + l.mu)) * Eigen::Matrix2d::Identity()) /
         (2.0 * l.mu);
}

}  // namespace

TEST_CASE("uniform beta (T - T0) on a free body is the dilation -s / (2 (lambda + mu)) (x - x0)",
          "[fem][thermal]") {
  const double E = 3.0, nu = 0.3, beta = 0.5, T = 1.4, T0 = 0.2;
  const Lame l = lame_plane_strain(E, nu);
  const double alpha = -beta * (T - T0) / (2.0 * (l.lambda + l.mu));
  ElasticityCoefficients c;
  c.young = E;
  c.poisson = nu;
  c.beta = beta;
  c.temperature = T;
  c.reference_temperature = T0;
  for (int p = 1; p <= 6; ++p) {
    INFO("p = " << p);
    Mesh m = unit_square(3, p);
    const int a = node_at(m, {0.0, 0.0}), b = node_at(m, {1.0, 0.0});
    const std::vector<int> boundary = square_boundary(m);
    warp(m, 0.04);
    const Eigen::Vector2d x0 = m.x.col(a);
    auto exact = [&](const Eigen::Vector2d& x) -> Eigen::Vector2d { return alpha * (x - x0); };

    // Free boundary, rigid motions fixed at two nodes: the dilation.
    DirichletBC two_nodes;
    two_nodes.fix(a, Eigen::Vector2d::Zero());
    two_nodes.fix(b, 1, exact(m.x.col(b))(1));
    const ElasticitySolution free = solve_elasticity(m, c, two_nodes);
    CHECK((free.u - interpolate(m, exact)).cwiseAbs().maxCoeff() < 1e-12);
    // Clamped boundary: the uniform thermal stress is self-equilibrated, u = 0.
    DirichletBC clamped;
    for (int i : boundary) clamped.fix(i, Eigen::Vector2d::Zero());
    CHECK(solve_elasticity(m, c, clamped).u.cwiseAbs().maxCoeff() < 1e-14);
  }
}

TEST_CASE("sliding walls x = 0, y = 0 and uniform T - T0: u = alpha x", "[fem][thermal]") {
  const Lame l = lame_plane_strain(1.0, 0.4);
  const double s = -0.2;  // beta (T - T0) < 0: expansion
  const double alpha = -s / (2.0 * (l.lambda + l.mu));
  ElasticityCoefficients c;
  c.beta = 1.0;
  c.temperature = s;
  for (int p : {1, 3, 5}) {
    INFO("p = " << p);
    const Mesh m = unit_square(4, p);
    DirichletBC bc;
    for (int i = 0; i < m.num_nodes(); ++i) {
      if (m.x(0, i) < 1e-12) bc.fix(i, 0, 0.0);
      if (m.x(1, i) < 1e-12) bc.fix(i, 1, 0.0);
    }
    const ElasticitySolution sol = solve_elasticity(m, c, bc);
    CHECK((sol.u - alpha * m.x).cwiseAbs().maxCoeff() < 1e-13);
    CHECK(alpha > 0.0);
  }
}

TEST_CASE("a uniform anisotropic thermal stress S gives the uniform strain -C^-1 S",
          "[fem][thermal]") {
  const Lame l = lame_plane_strain(1.0, 0.45);
  Eigen::Matrix2d S;
  S << 0.3, 0.1, 0.1, -0.05;
  const Eigen::Matrix2d eps = -compliance(l, S);
  ElasticityCoefficients c;
  c.poisson = 0.45;
  c.anisotropic_stress = S;
  for (int p = 1; p <= 6; ++p) {
    INFO("p = " << p);
    Mesh m = unit_square(3, p);
    const int a = node_at(m, {0.0, 0.0}), b = node_at(m, {1.0, 0.0});
    warp(m, 0.04);
    const Eigen::Vector2d x0 = m.x.col(a);
    auto exact = [&](const Eigen::Vector2d& x) -> Eigen::Vector2d { return eps * (x - x0); };
    DirichletBC bc;
    bc.fix(a, Eigen::Vector2d::Zero());
    bc.fix(b, 1, exact(m.x.col(b))(1));
    const ElasticitySolution s = solve_elasticity(m, c, bc);
    CHECK((s.u - interpolate(m, exact)).cwiseAbs().maxCoeff() < 1e-11);  // |u| ~ 0.4, nu = 0.45
  }
}
