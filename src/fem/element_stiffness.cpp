#include "fem/element_stiffness.h"

namespace homesh {

void element_stiffness_lower(const ElementGeometry& g, const Eigen::VectorXd& lambda,
                             const Eigen::VectorXd& mu, Eigen::MatrixXd& K,
                             Eigen::MatrixXd& scratch) {
  const Eigen::Index n = g.dNdx.rows(), nq = g.dNdx.cols();
  K.resize(2 * n, 2 * n);
  // Each block is a sum of G1 diag(w c) G2^T over the terms of Eq 4.15 (weights
  // w (lambda + 2 mu), w mu, w lambda), two terms at once as one product over 2 #points:
  // scratch = [G1 diag(w c) G1' diag(w c')], D = [dN/dx dN/dy] or [dN/dy dN/dx]. The
  // diagonal blocks are symmetric: their lower triangles only.
  auto A = K.topLeftCorner(n, n);
  auto B = K.bottomLeftCorner(n, n);  // B^T: int lambda dNi/dy dNj/dx + mu dNi/dx dNj/dy
  auto C = K.bottomRightCorner(n, n);
  thread_local Eigen::MatrixXd D;
  D.resize(n, 2 * nq);
  scratch.resize(n, 2 * nq);
  const Eigen::VectorXd stiff = g.weight.cwiseProduct(lambda + 2.0 * mu);
  const Eigen::VectorXd shear = g.weight.cwiseProduct(mu);
  const Eigen::VectorXd lame = g.weight.cwiseProduct(lambda);
  D.leftCols(nq) = g.dNdx;
  D.rightCols(nq) = g.dNdy;
  scratch.leftCols(nq).noalias() = g.dNdx * stiff.asDiagonal();
  scratch.rightCols(nq).noalias() = g.dNdy * shear.asDiagonal();
  A.triangularView<Eigen::Lower>() = scratch * D.transpose();
  scratch.leftCols(nq).noalias() = g.dNdx * shear.asDiagonal();
  scratch.rightCols(nq).noalias() = g.dNdy * stiff.asDiagonal();
  C.triangularView<Eigen::Lower>() = scratch * D.transpose();
  D.leftCols(nq) = g.dNdy;
  D.rightCols(nq) = g.dNdx;
  scratch.rightCols(nq).noalias() = g.dNdy * lame.asDiagonal();
  B.noalias() = scratch * D.transpose();
}

Eigen::MatrixXd element_stiffness(const ElementGeometry& g, const Eigen::VectorXd& lambda,
                                  const Eigen::VectorXd& mu) {
  Eigen::MatrixXd K, scratch;
  element_stiffness_lower(g, lambda, mu, K, scratch);
  // Exactly symmetric: the upper triangle mirrors the lower one.
  Eigen::MatrixXd symmetric = K.selfadjointView<Eigen::Lower>();
  return symmetric;
}

Eigen::MatrixXd element_stiffness(const Eigen::Matrix2Xd& X, const ElementTabulation& tab,
                                  const Eigen::VectorXd& lambda, const Eigen::VectorXd& mu) {
  return element_stiffness(element_geometry(X, tab), lambda, mu);
}

}  // namespace homesh
