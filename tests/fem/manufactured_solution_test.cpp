// Convergence on a manufactured smooth solution: L2 error O(h^(p+1)), energy
// error O(h^p) on structured meshes of the unit square.
#include <catch2/catch.hpp>
#include <cmath>

#include "fem/solve_elasticity.h"
#include "fem_test_support.h"

using namespace homesh;
using namespace homesh::fem_test;

namespace {

// u = (sin(pi x) sin(pi y), e^x cos y); with constant Lame constants
// div sigma = mu lap(u) + (lambda + mu) grad(div u), so f = -div sigma with
//   lap(u) = (-2 pi^2 sin(pi x) sin(pi y), 0),
//   grad(div u) = (-pi^2 sin(pi x) sin(pi y) - e^x sin y, pi^2 cos(pi x) cos(pi y) - e^x cos y).
Eigen::Vector2d exact(const Eigen::Vector2d& p) {
  const double x = p(0), y = p(1);
  return {std::sin(M_PI * x) * std::sin(M_PI * y), std::exp(x) * std::cos(y)};
}

Eigen::Matrix2d exact_gradient(const Eigen::Vector2d& p) {
  const double x = p(0), y = p(1);
  Eigen::Matrix2d G;
  G << M_PI * std::cos(M_PI * x) * std::sin(M_PI * y),
      M_PI * std::sin(M_PI * x) * std::cos(M_PI * y), std::exp(x) * std::cos(y),
      -std::exp(x) * std::sin(y);
  return G;
}

Eigen::Vector2d body_force(const Lame& l, const Eigen::Vector2d& p) {
  const double x = p(0), y = p(1), pi2 = M_PI * M_PI;
  const double ss = std::sin(M_PI * x) * std::sin(M_PI * y);
  const Eigen::Vector2d laplacian(-2.0 * pi2 * ss, 0.0);
  const Eigen::Vector2d grad_div(
      -pi2 * ss - std::exp(x) * std::sin(y),
      pi2 * std::cos(M_PI * x) * std::cos(M_PI * y) - std::exp(x) * std::cos(y));
  return -(l.mu * laplacian + (l.lambda + l.mu) * grad_div);
}

}  // namespace

TEST_CASE("manufactured solution: L2 error at rate p + 1 and energy error at rate p, p = 1..4",
          "[fem][convergence]") {
  const double E = 1.0, nu = 0.3;
  const Lame l = lame_plane_strain(E, nu);
  ElasticityCoefficients c;
  c.young = E;
  c.poisson = nu;
  c.body_force = [&l](const QuadraturePoint& q) { return body_force(l, q.x); };
  for (int p = 1; p <= 4; ++p) {
    ErrorNorms previous;
    for (int n : {4, 8, 16}) {
      const Mesh m = unit_square(n, p);
      DirichletBC bc;
      for (int i : square_boundary(m)) bc.fix(i, exact(m.x.col(i)));
      const ElasticitySolution s = solve_elasticity(m, c, bc);
      const ErrorNorms e = error_norms(m, s.u, exact, exact_gradient, l.lambda, l.mu);
      if (n == 16) {
        INFO("p = " << p << ": L2 " << previous.l2 << " -> " << e.l2 << ", energy "
                    << previous.energy << " -> " << e.energy);
        CHECK(std::log2(previous.l2 / e.l2) == Approx(p + 1).margin(0.2));
        CHECK(std::log2(previous.energy / e.energy) == Approx(p).margin(0.2));
      }
      previous = e;
    }
  }
}
