#include "element/tet_lagrange_basis.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "core/error.h"
#include "core/mesh.h"

using namespace homesh;

namespace {

// Random points of the reference tetrahedron.
Eigen::Matrix3Xd random_points(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  Eigen::Matrix3Xd x(3, n);
  for (int q = 0; q < n;) {
    const Eigen::Vector3d y(U(rng), U(rng), U(rng));
    if (y.sum() <= 1) x.col(q++) = y;
  }
  return x;
}

}  // namespace

TEST_CASE("TetLagrangeBasis: 1 at its node, 0 at the others, a partition of unity", "[element]") {
  for (int p = 1; p <= kMaxOrder; ++p) {
    INFO("p = " << p);
    const TetLagrangeBasis b(p);
    REQUIRE(b.size() == tetrahedron_node_count(p));
    double off = 0;
    for (int k = 0; k < b.size(); ++k) {
      Eigen::VectorXd N = b.values(b.nodes().col(k));
      CHECK(N(k) == Approx(1).margin(1e-9));
      N(k) = 0;
      off = std::max(off, N.cwiseAbs().maxCoeff());
    }
    CHECK(off < 1e-9);
    const Eigen::Matrix3Xd x = random_points(20, 7 + p);
    for (Eigen::Index q = 0; q < x.cols(); ++q) {
      CHECK(b.values(x.col(q)).sum() == Approx(1).margin(1e-10));
      CHECK(b.gradients(x.col(q)).rowwise().sum().norm() < 1e-8);
    }
  }
  CHECK_THROWS_AS(TetLagrangeBasis(0), Error);
  CHECK_THROWS_AS(TetLagrangeBasis(kMaxOrder + 1), Error);
}

TEST_CASE("TetLagrangeBasis reproduces polynomials of degree p and their gradients", "[element]") {
  for (int p = 1; p <= 6; ++p) {
    INFO("p = " << p);
    const TetLagrangeBasis b(p);
    // f = u^a v^c w^e, a + c + e = p: a monomial of the highest degree.
    const int a = p / 2, c = (p + 1) / 3, e = p - a - c;
    auto f = [&](const Eigen::Vector3d& x) {
      return std::pow(x(0), a) * std::pow(x(1), c) * std::pow(x(2), e);
    };
    auto grad = [&](const Eigen::Vector3d& x) {
      const double u = x(0), v = x(1), w = x(2);
      return Eigen::Vector3d(a ? a * std::pow(u, a - 1) * std::pow(v, c) * std::pow(w, e) : 0.0,
                             c ? c * std::pow(u, a) * std::pow(v, c - 1) * std::pow(w, e) : 0.0,
                             e ? e * std::pow(u, a) * std::pow(v, c) * std::pow(w, e - 1) : 0.0);
    };
    Eigen::VectorXd F(b.size());
    for (int k = 0; k < b.size(); ++k) F(k) = f(b.nodes().col(k));
    const Eigen::Matrix3Xd x = random_points(20, 3 + p);
    for (Eigen::Index q = 0; q < x.cols(); ++q) {
      CHECK(b.values(x.col(q)).dot(F) == Approx(f(x.col(q))).margin(1e-12));
      CHECK((b.gradients(x.col(q)) * F - grad(x.col(q))).norm() < 1e-10);
    }
  }
}
