// Convergence on a manufactured smooth solution: L2 error O(h^(p+1)), energy
// error O(h^p) on structured meshes of the unit square.
#include <catch2/catch.hpp>
#include <cmath>

#include "fem/solve_elasticity.h"
#include "fem_test_support.h"

using namespace homesh;
using namespace homesh::fem_test;

TEST_CASE("manufactured solution: L2 error at rate p + 1 and energy error at rate p, p = 1..4",
          "[fem][convergence]") {
  const double E = 1.0, nu = 0.3;
  const Lame l = lame_plane_strain(E, nu);
  ElasticityCoefficients c;
  c.young = E;
  c.poisson = nu;
  c.body_force = [&l](const QuadraturePoint& q) { return manufactured_body_force(l, q.x); };
  for (int p = 1; p <= 4; ++p) {
    ErrorNorms previous;
    for (int n : {4, 8, 16}) {
      const Mesh m = unit_square(n, p);
      DirichletBC bc;
      for (int i : square_boundary(m)) bc.fix(i, manufactured_exact(m.x.col(i)));
      const ElasticitySolution s = solve_elasticity(m, c, bc);
      const ErrorNorms e =
          error_norms(m, s.u, manufactured_exact, manufactured_gradient, l.lambda, l.mu);
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
