// Patch tests: a linear displacement prescribed on the boundary is reproduced
// exactly inside, on straight and curved elements of order 1..6, also with
// spatially varying E, nu and thermal load balanced by the matching body force.
#include <catch2/catch.hpp>

#include "fem/solve_elasticity.h"
#include "fem_test_support.h"

using namespace homesh;
using namespace homesh::fem_test;

namespace {

DirichletBC boundary_condition(const Mesh& m, const std::vector<int>& nodes) {
  DirichletBC bc;
  for (int i : nodes) bc.fix(i, patch_field(m.x.col(i)));
  return bc;
}

double max_error(const Mesh& m, const Eigen::Matrix2Xd& u) {
  return (u - interpolate(m, patch_field)).cwiseAbs().maxCoeff();
}

}  // namespace

TEST_CASE("patch test: a linear field is reproduced on straight and curved elements, p = 1..6",
          "[fem][patch]") {
  for (int p = 1; p <= 6; ++p) {
    for (double curve : {0.0, 0.04}) {
      INFO("p = " << p << ", curve = " << curve);
      Mesh m = unit_square(3, p);
      const std::vector<int> boundary = square_boundary(m);
      warp(m, curve);
      ElasticityCoefficients c;
      c.poisson = 0.45;
      const ElasticitySolution s = solve_elasticity(m, c, boundary_condition(m, boundary));
      CHECK(max_error(m, s.u) < 1e-13);
    }
  }
}

TEST_CASE("patch test with varying E, nu and temperature balanced by a body force, p = 1..6",
          "[fem][patch]") {
  // For u = G x + c, eps is constant and div sigma = tr(eps) grad(lambda) +
  // 2 eps grad(mu) + grad(beta (T - T0)). With lambda, mu and beta (T - T0) affine
  // in x the body force f = -div sigma is constant and u solves the problem;
  // on curved elements the integrands are polynomials of degree 3p - 2 in (u, v)
  // (an affine coefficient of x(u, v) times dN/dx det J, or N f det J), so the
  // quadrature margin is p.
  const Eigen::Vector2d grad_lambda(0.3, -0.2), grad_mu(0.1, 0.25), grad_s(-0.4, 0.15);
  const Eigen::Matrix2d eps = 0.5 * (kPatchGradient + kPatchGradient.transpose());
  const Eigen::Vector2d force = -(eps.trace() * grad_lambda + 2.0 * eps * grad_mu + grad_s);
  auto lambda = [&](const Eigen::Vector2d& x) { return 1.0 + grad_lambda.dot(x); };
  auto mu = [&](const Eigen::Vector2d& x) { return 0.8 + grad_mu.dot(x); };
  ElasticityCoefficients c;
  // (E, nu) of (lambda, mu): nu = lambda / (2 (lambda + mu)), E = 2 mu (1 + nu).
  c.poisson = [&](const QuadraturePoint& q) {
    return lambda(q.x) / (2.0 * (lambda(q.x) + mu(q.x)));
  };
  c.young = [&](const QuadraturePoint& q) {
    return 2.0 * mu(q.x) * (1.0 + lambda(q.x) / (2.0 * (lambda(q.x) + mu(q.x))));
  };
  c.beta = 2.0;
  c.reference_temperature = 0.5;
  c.temperature = [&](const QuadraturePoint& q) { return 0.5 + 0.5 * (0.3 + grad_s.dot(q.x)); };
  c.body_force = force;
  for (int p = 1; p <= 6; ++p) {
    INFO("p = " << p);
    Mesh m = unit_square(3, p);
    const std::vector<int> boundary = square_boundary(m);
    warp(m, 0.04);
    ElasticityOptions options;
    options.assembly.quadrature_margin = p;
    const ElasticitySolution s = solve_elasticity(m, c, boundary_condition(m, boundary), options);
    CHECK(max_error(m, s.u) < 1e-12);
  }
}
