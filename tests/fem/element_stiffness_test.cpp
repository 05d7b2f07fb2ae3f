#include "fem/element_stiffness.h"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "core/mesh.h"
#include "element/reference_nodes.h"
#include "fem/elasticity_coefficients.h"
#include "fem/element_load.h"

using namespace homesh;

namespace {

// The nodes of order p of a triangle with corners P (2 by 3), straight sides,
// plus a random perturbation of the high-order nodes of size <= `curve`.
Eigen::Matrix2Xd element_nodes(const Eigen::Matrix<double, 2, 3>& P, int p, double curve,
                               unsigned seed) {
  const Eigen::Matrix2Xd uv = reference_nodes(p);
  Eigen::Matrix2d A;
  A << P.col(1) - P.col(0), P.col(2) - P.col(0);
  Eigen::Matrix2Xd X = (A * uv).colwise() + P.col(0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-curve, curve);
  for (Eigen::Index i = 3; i < X.cols(); ++i) X.col(i) += Eigen::Vector2d(d(rng), d(rng));
  return X;
}

Eigen::Matrix<double, 2, 3> corners() {
  Eigen::Matrix<double, 2, 3> P;
  P << 0.3, 1.4, 0.6,  //
      -0.2, 0.1, 1.2;
  return P;
}

// Element dofs [u_1..u_n, v_1..v_n] of the nodal field G x + c.
Eigen::VectorXd linear_field(const Eigen::Matrix2Xd& X, const Eigen::Matrix2d& G,
                             const Eigen::Vector2d& c) {
  const Eigen::Matrix2Xd U = (G * X).colwise() + c;
  Eigen::VectorXd d(2 * X.cols());
  d << U.row(0).transpose(), U.row(1).transpose();
  return d;
}

}  // namespace

TEST_CASE("element_stiffness is symmetric with exactly the 3 rigid motions in its kernel, p = 1..6",
          "[fem][element_stiffness]") {
  const Lame lame = lame_plane_strain(1.0, 0.3);
  for (int p = 1; p <= 6; ++p) {
    for (double curve : {0.0, 0.03}) {
      INFO("p = " << p << ", curve = " << curve);
      const ElementTabulation tab = tabulate_element(p, stiffness_quadrature_degree(p, 2));
      const Eigen::Index nq = tab.rule.weights.size();
      const Eigen::Matrix2Xd X = element_nodes(corners(), p, curve / p, 7u + p);
      const Eigen::MatrixXd K =
          element_stiffness(X, tab, Eigen::VectorXd::Constant(nq, lame.lambda),
                            Eigen::VectorXd::Constant(nq, lame.mu));
      CHECK((K - K.transpose()).cwiseAbs().maxCoeff() < 1e-13 * K.cwiseAbs().maxCoeff());
      Eigen::Matrix2d rotation;
      rotation << 0.0, -1.0, 1.0, 0.0;
      for (const Eigen::VectorXd& rigid : {linear_field(X, Eigen::Matrix2d::Zero(), {1.0, 0.0}),
                                           linear_field(X, Eigen::Matrix2d::Zero(), {0.0, 1.0}),
                                           linear_field(X, rotation, {0.2, -0.1})})
        CHECK((K * rigid).norm() < 1e-12 * K.norm() * rigid.norm());
      const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
      CHECK(std::abs(ev(2)) < 1e-12 * ev.maxCoeff());
      CHECK(ev(3) > 1e-6 * ev.maxCoeff());
    }
  }
}

TEST_CASE("element_stiffness gives the exact strain energy of a linear field, p = 1..6",
          "[fem][element_stiffness]") {
  // u = G x: eps = sym(G) constant, energy u^T K u = |e| (2 mu eps:eps + lambda tr(eps)^2),
  // exact on curved elements too since dN/dx det J is a polynomial of degree 2(p-1).
  const Lame lame = lame_plane_strain(2.5, 0.35);
  Eigen::Matrix2d G;
  G << 0.3, -0.7, 0.2, 0.45;
  const Eigen::Matrix2d eps = 0.5 * (G + G.transpose());
  const double density =
      2.0 * lame.mu * eps.squaredNorm() + lame.lambda * eps.trace() * eps.trace();
  for (int p = 1; p <= 6; ++p) {
    INFO("p = " << p);
    const ElementTabulation tab = tabulate_element(p, stiffness_quadrature_degree(p, 0));
    const Eigen::Index nq = tab.rule.weights.size();
    const Eigen::Matrix2Xd X = element_nodes(corners(), p, 0.04 / p, 11u + p);
    const ElementGeometry g = element_geometry(X, tab);
    const double area = g.weight.sum();
    const Eigen::VectorXd d = linear_field(X, G, {0.1, 0.2});
    const Eigen::MatrixXd K = element_stiffness(g, Eigen::VectorXd::Constant(nq, lame.lambda),
                                                Eigen::VectorXd::Constant(nq, lame.mu));
    CHECK(d.dot(K * d) == Approx(area * density).epsilon(1e-12));
  }
}

TEST_CASE("element_stiffness of the linear triangle is |e| B^T D B", "[fem][element_stiffness]") {
  const Lame lame = lame_plane_strain(1.0, 0.25);
  const Eigen::Matrix2Xd X = corners();
  const ElementTabulation tab = tabulate_element(1, 0);
  const Eigen::MatrixXd K = element_stiffness(X, tab, Eigen::VectorXd::Constant(1, lame.lambda),
                                              Eigen::VectorXd::Constant(1, lame.mu));
  // Constant-strain triangle: dN_i/dx = (y_j - y_k) / 2A, dN_i/dy = (x_k - x_j) / 2A.
  const double two_area =
      (X(0, 1) - X(0, 0)) * (X(1, 2) - X(1, 0)) - (X(0, 2) - X(0, 0)) * (X(1, 1) - X(1, 0));
  Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();  // Voigt xx, yy, 2xy
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double bx = (X(1, j) - X(1, k)) / two_area, by = (X(0, k) - X(0, j)) / two_area;
    B(0, i) = bx;
    B(1, 3 + i) = by;
    B(2, i) = by;
    B(2, 3 + i) = bx;
  }
  Eigen::Matrix3d D;
  D << lame.lambda + 2 * lame.mu, lame.lambda, 0, lame.lambda, lame.lambda + 2 * lame.mu, 0, 0, 0,
      lame.mu;
  const Eigen::MatrixXd expected = 0.5 * two_area * B.transpose() * D * B;
  CHECK((K - expected).cwiseAbs().maxCoeff() < 1e-14 * expected.cwiseAbs().maxCoeff());
}

TEST_CASE("element_stiffness of straight elements is exact at degree 2(p-1)",
          "[fem][element_stiffness]") {
  for (int p = 1; p <= 6; ++p) {
    INFO("p = " << p);
    const Eigen::Matrix2Xd X = element_nodes(corners(), p, 0.0, 1u);
    const ElementTabulation exact = tabulate_element(p, stiffness_quadrature_degree(p, 0));
    const ElementTabulation fine = tabulate_element(p, stiffness_quadrature_degree(p, 6));
    auto stiffness = [&X](const ElementTabulation& tab) {
      const Eigen::Index nq = tab.rule.weights.size();
      return element_stiffness(X, tab, Eigen::VectorXd::Constant(nq, 0.7),
                               Eigen::VectorXd::Constant(nq, 0.4));
    };
    const Eigen::MatrixXd K0 = stiffness(exact), K1 = stiffness(fine);
    CHECK((K0 - K1).cwiseAbs().maxCoeff() < 1e-12 * K1.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("element_load integrates the body force and balances a uniform thermal stress",
          "[fem][element_load]") {
  for (int p = 1; p <= 6; ++p) {
    INFO("p = " << p);
    const ElementTabulation tab = tabulate_element(p, stiffness_quadrature_degree(p, 2));
    const Eigen::Index nq = tab.rule.weights.size();
    const Eigen::Matrix2Xd X = element_nodes(corners(), p, 0.03 / p, 5u + p);
    const ElementGeometry g = element_geometry(X, tab);
    const Eigen::Index n = X.cols();
    // Constant f: the loads sum to |e| f (the basis is a partition of unity).
    Eigen::Matrix2Xd f(2, nq);
    f.row(0).setConstant(1.5);
    f.row(1).setConstant(-0.5);
    const Eigen::VectorXd fe = element_load(g, tab.N, f, Eigen::Matrix3Xd::Zero(3, nq));
    CHECK(fe.head(n).sum() == Approx(1.5 * g.weight.sum()).epsilon(1e-13));
    CHECK(fe.tail(n).sum() == Approx(-0.5 * g.weight.sum()).epsilon(1e-13));
    // A constant stress S does the work -|e| S : grad(u) on u = G x.
    Eigen::Matrix3Xd sigma(3, nq);
    sigma.row(0).setConstant(0.8);
    sigma.row(1).setConstant(-0.3);
    sigma.row(2).setConstant(0.25);
    Eigen::Matrix2d G;
    G << 0.3, -0.7, 0.2, 0.45;
    const Eigen::VectorXd ft = element_load(g, tab.N, Eigen::Matrix2Xd::Zero(2, nq), sigma);
    const double work = 0.8 * G(0, 0) - 0.3 * G(1, 1) + 0.25 * (G(0, 1) + G(1, 0));
    CHECK(ft.dot(linear_field(X, G, {0.4, 0.1})) == Approx(-g.weight.sum() * work).epsilon(1e-12));
  }
}
