#include "fem/tet_elasticity.h"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>
#include <random>

#include "element/tet_reference_nodes.h"

using namespace homesh;

namespace {

// The order-p tetrahedron with corners `corners` (3 by 4), straight-sided, its
// non-corner nodes moved by up to `bend` in random directions (seeded).
Eigen::Matrix3Xd element(const Eigen::Matrix<double, 3, 4>& corners, int p, double bend) {
  const Eigen::Matrix3Xd r = tetrahedron_nodes(p);
  Eigen::Matrix3Xd X(3, r.cols());
  std::mt19937 rng(11 + p);
  std::uniform_real_distribution<double> jitter(-1.0, 1.0);
  for (Eigen::Index k = 0; k < r.cols(); ++k) {
    X.col(k) = corners.col(0) + r(0, k) * (corners.col(1) - corners.col(0)) +
               r(1, k) * (corners.col(2) - corners.col(0)) +
               r(2, k) * (corners.col(3) - corners.col(0));
    if (k >= 4) X.col(k) += bend * Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
  }
  return X;
}

Eigen::Matrix<double, 3, 4> corners() {
  Eigen::Matrix<double, 3, 4> c;
  c << 0.1, 1.3, 0.2, 0.4,  //
      -0.2, 0.1, 1.1, 0.3,  //
      0.0, 0.2, -0.1, 0.9;
  return c;
}

// The displacement u(x) = A x + b at X's nodes, node-major.
Eigen::VectorXd linear_field(const Eigen::Matrix3Xd& X, const Eigen::Matrix3d& A,
                             const Eigen::Vector3d& b) {
  Eigen::VectorXd u(3 * X.cols());
  for (Eigen::Index k = 0; k < X.cols(); ++k) u.segment<3>(3 * k) = A * X.col(k) + b;
  return u;
}

}  // namespace

TEST_CASE("tetrahedron_stiffness: energy of a linear field is the exact strain energy, p = 1..5",
          "[fem][tet_elasticity]") {
  const double lambda = 1.7, mu = 0.6;
  Eigen::Matrix3d A;
  A << 0.3, -0.2, 0.5, 0.1, 0.7, -0.4, 0.2, 0.6, -0.3;
  const Eigen::Matrix3d eps = (A + A.transpose()) / 2;
  for (int p = 1; p <= 5; ++p) {
    INFO("p = " << p);
    const Eigen::Matrix3Xd X = element(corners(), p, 0.0);
    const TetTabulation t = tetrahedron_tabulation(p, 2 * (p - 1));
    double volume = 0;
    const Eigen::MatrixXd K = tetrahedron_stiffness(X, t, lambda, mu, &volume);
    Eigen::Matrix3d J;
    J << X.col(1) - X.col(0), X.col(2) - X.col(0), X.col(3) - X.col(0);
    CHECK(volume == Approx(J.determinant() / 6).epsilon(1e-13));
    // u^T K u = int sigma : eps = V (lambda tr(eps)^2 + 2 mu eps : eps).
    const Eigen::VectorXd u = linear_field(X, A, Eigen::Vector3d(0.3, -1, 2));
    const double exact =
        volume * (lambda * eps.trace() * eps.trace() + 2 * mu * eps.cwiseAbs2().sum());
    CHECK(u.dot(K * u) == Approx(exact).epsilon(1e-11));
    CHECK((K - K.transpose()).cwiseAbs().maxCoeff() < 1e-12 * K.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("tetrahedron_stiffness: six rigid motions span the kernel, straight and curved",
          "[fem][tet_elasticity]") {
  for (int p = 1; p <= 4; ++p)
    for (double bend : {0.0, 0.04}) {
      if (p == 1 && bend > 0) continue;
      INFO("p = " << p << ", bend = " << bend);
      const Eigen::Matrix3Xd X = element(corners(), p, bend);
      const TetTabulation t = tetrahedron_tabulation(p, 2 * p);
      const Eigen::MatrixXd K = tetrahedron_stiffness(X, t, 1.0, 0.5);
      const double scale = K.cwiseAbs().maxCoeff();
      // Translations and infinitesimal rotations: K u = 0.
      for (int d = 0; d < 3; ++d) {
        Eigen::Vector3d b = Eigen::Vector3d::Zero();
        b(d) = 1;
        CHECK((K * linear_field(X, Eigen::Matrix3d::Zero(), b)).norm() < 1e-11 * scale);
        Eigen::Matrix3d W = Eigen::Matrix3d::Zero();
        W((d + 1) % 3, (d + 2) % 3) = 1;
        W((d + 2) % 3, (d + 1) % 3) = -1;
        CHECK((K * linear_field(X, W, Eigen::Vector3d::Zero())).norm() < 1e-11 * scale);
      }
      // Nothing else: exactly six zero eigenvalues, the rest positive.
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig((K + K.transpose()) / 2);
      const Eigen::VectorXd ev = eig.eigenvalues();
      CHECK(std::abs(ev(5)) < 1e-10 * scale);
      CHECK(ev(6) > 1e-6 * scale);
    }
}

TEST_CASE("tetrahedron_stiffness: the closed form equals the quadrature on straight elements",
          "[fem][tet_elasticity]") {
  for (int p = 2; p <= 4; ++p) {
    INFO("p = " << p);
    const TetTabulation t = tetrahedron_tabulation(p, 2 * (p - 1));
    const Eigen::Matrix3Xd X = element(corners(), p, 0.0);
    // A bend of 1e-9 leaves the affine path (tolerance 1e-12) for the quadrature.
    const Eigen::Matrix3Xd Y = element(corners(), p, 1e-9);
    const Eigen::MatrixXd KX = tetrahedron_stiffness(X, t, 1.3, 0.7);
    const Eigen::MatrixXd KY = tetrahedron_stiffness(Y, t, 1.3, 0.7);
    CHECK((KX - KY).cwiseAbs().maxCoeff() < 1e-6 * KX.cwiseAbs().maxCoeff());
  }
}
