#include <catch2/catch.hpp>
#include <random>

#include "core/error.h"
#include "core/mesh.h"
#include "element/tet_lagrange_basis.h"
#include "element/tet_reference_nodes.h"
#include "quality/jacobian_bounds.h"
#include "quality/tet_bezier_jacobian.h"

using namespace homesh;

namespace {

// The order-p tetrahedron whose nodes are the reference nodes mapped by f.
template <class Map>
Eigen::Matrix3Xd mapped(int p, Map f) {
  const Eigen::Matrix3Xd r = tetrahedron_nodes(p);
  Eigen::Matrix3Xd X(3, r.cols());
  for (Eigen::Index k = 0; k < r.cols(); ++k) X.col(k) = f(Eigen::Vector3d(r.col(k)));
  return X;
}

}  // namespace

TEST_CASE("tetrahedron_jacobian_bounds: det J = 6 volume of a straight tetrahedron, p = 1..5",
          "[quality][bezier]") {
  Eigen::Matrix3d A;
  A << 2, 0.3, -0.2, 0.1, 1.5, 0.4, -0.3, 0.2, 0.8;
  const Eigen::Vector3d b(1, -2, 0.5);
  for (int p = 1; p <= kMaxTetJacobianOrder; ++p) {
    INFO("p = " << p);
    const Eigen::Matrix3Xd X = mapped(p, [&](const Eigen::Vector3d& x) { return A * x + b; });
    const JacobianBounds r = tetrahedron_jacobian_bounds(X, p);
    // The collocation inverse at degree 12 (p = 5) is good to some 1e-9.
    CHECK(r.min_lower == Approx(A.determinant()).epsilon(1e-8));
    CHECK(r.max_upper == Approx(A.determinant()).epsilon(1e-8));
    CHECK(r.valid_certified);
    CHECK(r.subdivisions == 0);
    CHECK(scaled_jacobian_ratio(r) == Approx(1).epsilon(1e-8));
    // Its mirror image (x -> -x): det J = -det A, scored as the element itself.
    Eigen::Matrix3Xd Y = X;
    Y.row(0) *= -1;
    const JacobianBounds mirror = tetrahedron_jacobian_bounds(Y, p);
    CHECK(mirror.max_upper == Approx(-A.determinant()).epsilon(1e-8));
    CHECK(mirror.min_lower == Approx(-A.determinant()).epsilon(1e-8));
    CHECK(mirror.invalid_certified);
    CHECK(scaled_jacobian_ratio(mirror) == Approx(1).epsilon(1e-8));
  }
  CHECK_THROWS_AS(tetrahedron_jacobian_bounds(Eigen::Matrix3Xd::Zero(3, 9), 2), Error);
  CHECK_THROWS_AS(tetrahedron_jacobian_bezier(Eigen::Matrix3Xd::Zero(3, 56), 6), Error);
}

TEST_CASE("tetrahedron_jacobian_bounds: a stretched tetrahedron, det J = 1 + a w, certified",
          "[quality][bezier]") {
  // x = (u (1 + a w), v, w): J = [[1 + a w, 0, a u], [0, 1, 0], [0, 0, 1]], det J = 1 + a w,
  // from 1 at w = 0 to 1 + a at the corner (0, 0, 1); exact at p >= 2.
  for (int p = 2; p <= kMaxTetJacobianOrder; ++p)
    for (double a : {0.5, 3.0, -0.5, -1.5}) {
      INFO("p = " << p << ", a = " << a);
      const Eigen::Matrix3Xd X = mapped(p, [&](const Eigen::Vector3d& x) {
        return Eigen::Vector3d(x(0) * (1 + a * x(2)), x(1), x(2));
      });
      const JacobianBounds r = tetrahedron_jacobian_bounds(X, p);
      const double lo = std::min(1.0, 1 + a), hi = std::max(1.0, 1 + a);
      CHECK(r.converged);
      CHECK(r.min_lower <= lo + 1e-12);
      CHECK(r.min_upper == Approx(lo).margin(1e-12));  // a corner's exact value
      CHECK(r.max_upper >= hi - 1e-12);
      CHECK(r.max_lower == Approx(hi).margin(1e-12));
      CHECK(lo - r.min_lower <= r.tolerance + 1e-12);
      CHECK(r.max_upper - hi <= r.tolerance + 1e-12);
      CHECK(r.valid_certified == (a > -1));
      CHECK(r.invalid_certified == (a <= -1));
    }
}

TEST_CASE("tetrahedron_jacobian_bounds contain det J sampled over perturbed tetrahedra",
          "[quality][bezier]") {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int p = 2; p <= 4; ++p)
    for (int trial = 0; trial < 6; ++trial) {
      INFO("p = " << p << ", trial " << trial);
      Eigen::Matrix3Xd X = tetrahedron_nodes(p);
      const double amount = 0.05 * (trial + 1) / p;  // up to valid and invalid ones
      for (Eigen::Index k = 4; k < X.cols(); ++k)
        X.col(k) += amount * Eigen::Vector3d(U(rng), U(rng), U(rng));
      const JacobianBounds r = tetrahedron_jacobian_bounds(X, p);
      const TetLagrangeBasis basis(p);
      // det J on the degree-20 lattice (faces, edges and corners included, where the
      // extremes of a perturbed element often lie).
      double lo = 1e300, hi = -1e300;
      const Eigen::Matrix3Xd sample = tetrahedron_nodes(20);
      for (Eigen::Index s = 0; s < sample.cols(); ++s) {
        const double det = (X * basis.gradients(sample.col(s)).transpose()).determinant();
        lo = std::min(lo, det);
        hi = std::max(hi, det);
      }
      CHECK(r.converged);
      CHECK(r.min_lower <= lo + 1e-12);
      CHECK(r.max_upper >= hi - 1e-12);
      CHECK(r.min_upper - r.min_lower <= r.tolerance + 1e-12);
      // Refined to the tolerance: below the sampled minimum by little more.
      CHECK(r.min_lower >= lo - r.tolerance - 0.02 * (hi - lo));
      CHECK(r.max_upper <= hi + r.tolerance + 0.02 * (hi - lo));
      if (r.valid_certified) CHECK(lo > 0);
      if (lo <= 0) CHECK_FALSE(r.valid_certified);
    }
}
