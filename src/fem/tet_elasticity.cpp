#include "fem/tet_elasticity.h"

#include <Eigen/LU>
#include <cmath>

#include "element/tet_lagrange_basis.h"

namespace homesh {
namespace {

// True if X's nodes are the affine map of its corners at the reference nodes
// (to rounding): then J is constant and Ke has a closed form.
bool affine(const Eigen::Matrix3Xd& X, const Eigen::Matrix3Xd& reference) {
  const Eigen::Vector3d o = X.col(0);
  Eigen::Matrix3d A;
  A << X.col(1) - o, X.col(2) - o, X.col(3) - o;
  const double scale = A.cwiseAbs().maxCoeff();
  for (Eigen::Index k = 4; k < X.cols(); ++k)
    if ((o + A * reference.col(k) - X.col(k)).cwiseAbs().maxCoeff() > 1e-12 * scale) return false;
  return true;
}

// Ke from the gradients G (3 by n, constant over the element) times `w`.
void add_blocks(const Eigen::Matrix3Xd& G, double w, double lambda, double mu, Eigen::MatrixXd& K) {
  const Eigen::Index n = G.cols();
  const Eigen::MatrixXd dots = G.transpose() * G;  // grad Na . grad Nb
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index b = 0; b < n; ++b) {
      Eigen::Matrix3d block =
          lambda * G.col(a) * G.col(b).transpose() + mu * G.col(b) * G.col(a).transpose();
      block.diagonal().array() += mu * dots(a, b);
      K.block<3, 3>(3 * a, 3 * b) += w * block;
    }
}

}  // namespace

TetTabulation tetrahedron_tabulation(int p, int degree) {
  TetTabulation t;
  t.order = p;
  t.rule = tetrahedron_quadrature(degree);
  const TetLagrangeBasis basis(p);
  t.reference_nodes = basis.nodes();
  const auto n = static_cast<Eigen::Index>(basis.size());
  for (auto& m : t.products) m = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index q = 0; q < t.rule.points.cols(); ++q) {
    t.gradients.push_back(basis.gradients(t.rule.points.col(q)));
    const Eigen::Matrix3Xd& dN = t.gradients.back();
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s)
        t.products[3 * r + s].noalias() += t.rule.weights(q) * dN.row(r).transpose() * dN.row(s);
  }
  return t;
}

Eigen::MatrixXd tetrahedron_stiffness(const Eigen::Matrix3Xd& X, const TetTabulation& t,
                                      double lambda, double mu, double* volume) {
  const Eigen::Index n = X.cols();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  if (affine(X, t.reference_nodes)) {
    // Constant J: grad N_a = J^-T grad_ref N_a, so int dNa/dx_i dNb/dx_j dx =
    // det J sum_rs B_ir B_js P_rs(a, b), B = J^-T, P_rs = int dNa/du_r dNb/du_s.
    Eigen::Matrix3d J;
    J << X.col(1) - X.col(0), X.col(2) - X.col(0), X.col(3) - X.col(0);
    const double det = J.determinant();
    const Eigen::Matrix3d B = J.transpose().inverse();
    Eigen::MatrixXd D[9];  // D[3i+j](a, b) = int dNa/dx_i dNb/dx_j
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        D[3 * i + j] = Eigen::MatrixXd::Zero(n, n);
        for (int r = 0; r < 3; ++r)
          for (int s = 0; s < 3; ++s)
            if (B(i, r) != 0 && B(j, s) != 0)
              D[3 * i + j] += (det * B(i, r) * B(j, s)) * t.products[3 * r + s];
      }
    const Eigen::MatrixXd dots = D[0] + D[4] + D[8];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        // lambda int dNa/dx_i dNb/dx_j + mu int dNa/dx_j dNb/dx_i + mu delta_ij dots.
        const Eigen::MatrixXd block =
            lambda * D[3 * i + j] + mu * D[3 * j + i] + (i == j ? mu : 0.0) * dots;
        for (Eigen::Index a = 0; a < n; ++a)
          for (Eigen::Index b = 0; b < n; ++b) K(3 * a + i, 3 * b + j) = block(a, b);
      }
    if (volume) *volume = det / 6.0;
    return K;
  }
  Eigen::Matrix3Xd G(3, n);  // physical gradients, column k grad N_k
  double v = 0;
  for (std::size_t q = 0; q < t.gradients.size(); ++q) {
    const Eigen::Matrix3Xd& dN = t.gradients[q];
    const Eigen::Matrix3d J = X * dN.transpose();  // J_ir = dx_i / du_r
    const double w = t.rule.weights(static_cast<Eigen::Index>(q)) * J.determinant();
    v += w;
    G.noalias() = J.transpose().inverse() * dN;
    add_blocks(G, w, lambda, mu, K);
  }
  if (volume) *volume = v;
  return K;
}

}  // namespace homesh
