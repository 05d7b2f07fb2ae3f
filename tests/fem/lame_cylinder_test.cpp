// Lame's thick cylinder in plane strain on isoparametric curved elements: a
// quarter of the annulus 1 <= r <= 2 with the radial displacements of the two
// circles prescribed and symmetry (zero normal displacement, free tangential
// traction) on the two straight sides. Exact solution u = (A + B / r^2) x.
#include <catch2/catch.hpp>
#include <cmath>

#include "fem/solve_elasticity.h"
#include "fem_test_support.h"

using namespace homesh;
using namespace homesh::fem_test;

namespace {

constexpr double kInner = 1.0, kOuter = 2.0;

// u_r = A r + B / r with u_r(a) = ua, u_r(b) = ub:
//   A = (ub b - ua a) / (b^2 - a^2),  B = a b (ua b - ub a) / (b^2 - a^2).
struct RadialField {
  double A, B;
};
constexpr double kUa = 0.01, kUb = 0.004;
constexpr RadialField kExact{
    (kUb * kOuter - kUa * kInner) / (kOuter * kOuter - kInner * kInner),
    kInner* kOuter*(kUa* kOuter - kUb * kInner) / (kOuter * kOuter - kInner * kInner)};

Eigen::Vector2d exact(const Eigen::Vector2d& x) {
  return (kExact.A + kExact.B / x.squaredNorm()) * x;
}

// du_i/dx_j = (A + B / r^2) delta_ij - 2 B x_i x_j / r^4.
Eigen::Matrix2d exact_gradient(const Eigen::Vector2d& x) {
  const double r2 = x.squaredNorm();
  return (kExact.A + kExact.B / r2) * Eigen::Matrix2d::Identity() -
         2.0 * kExact.B / (r2 * r2) * x * x.transpose();
}

ErrorNorms solve(int n, int p) {
  const Mesh m = quarter_annulus(n, p, kInner, kOuter);
  DirichletBC bc;
  for (int i = 0; i < m.num_nodes(); ++i) {
    const Eigen::Vector2d x = m.x.col(i);
    const double r = x.norm();
    if (std::abs(r - kInner) < 1e-12 || std::abs(r - kOuter) < 1e-12) {
      bc.fix(i, exact(x));
    } else {
      if (std::abs(x(1)) < 1e-14) bc.fix(i, 1, 0.0);
      if (std::abs(x(0)) < 1e-14) bc.fix(i, 0, 0.0);
    }
  }
  ElasticityCoefficients c;
  c.poisson = 0.3;
  const ElasticitySolution s = solve_elasticity(m, c, bc);
  const Lame l = lame_plane_strain(1.0, 0.3);
  return error_norms(m, s.u, exact, exact_gradient, l.lambda, l.mu);
}

}  // namespace

TEST_CASE("Lame cylinder: optimal h-rates on curved isoparametric elements, p = 1..4",
          "[fem][lame]") {
  // Seen (n = 4 -> 8): L2 rates 2.00, 3.03, 3.96, 4.91; energy 1.00, 1.95, 2.94, 3.87.
  for (int p = 1; p <= 4; ++p) {
    const ErrorNorms coarse = solve(4, p), fine = solve(8, p);
    INFO("p = " << p << ": L2 " << coarse.l2 << " -> " << fine.l2 << ", energy " << coarse.energy
                << " -> " << fine.energy);
    CHECK(std::log2(coarse.l2 / fine.l2) == Approx(p + 1).margin(0.2));
    CHECK(std::log2(coarse.energy / fine.energy) == Approx(p).margin(0.2));
  }
}

TEST_CASE("Lame cylinder: the error falls by 5 or more per order on a fixed mesh, p = 1..6",
          "[fem][lame]") {
  // Seen on 8 elements: L2 1.2e-3, 3.6e-5, 4.0e-6, 2.3e-7, 2.0e-8, 1.8e-9;
  // energy 5.4e-3, 3.9e-4, 5.0e-5, 4.7e-6, 5.1e-7, 5.6e-8.
  ErrorNorms previous = solve(2, 1);
  for (int p = 2; p <= 6; ++p) {
    const ErrorNorms e = solve(2, p);
    INFO("p = " << p << ": L2 " << e.l2 << ", energy " << e.energy);
    CHECK(previous.l2 / e.l2 > 5.0);
    CHECK(previous.energy / e.energy > 5.0);
    previous = e;
  }
  CHECK(previous.l2 < 5e-9);
  CHECK(previous.energy < 1e-7);
}
