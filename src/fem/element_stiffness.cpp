#include "fem/element_stiffness.h"

namespace homesh {

void element_stiffness_lower(const ElementGeometry& g, const Eigen::VectorXd& lambda,
                             const Eigen::VectorXd& mu, Eigen::MatrixXd& K,
                             Eigen::MatrixXd& scratch) {
  const Eigen::Index n = g.dNdx.rows();
  K.resize(2 * n, 2 * n);
  // Each block is G1 diag(w c) G2^T summed over the terms of Eq 4.15, with
  // scratch = G1 diag(w c); weights w (lambda + 2 mu), w mu, w lambda.
  auto A = K.topLeftCorner(n, n);
  auto B = K.bottomLeftCorner(n, n);  // B^T: int lambda dNi/dy dNj/dx + mu dNi/dx dNj/dy
  auto C = K.bottomRightCorner(n, n);
  scratch.noalias() = g.dNdx * (g.weight.cwiseProduct(lambda + 2.0 * mu)).asDiagonal();
  A.noalias() = scratch * g.dNdx.transpose();
  scratch.noalias() = g.dNdy * (g.weight.cwiseProduct(mu)).asDiagonal();
  A.noalias() += scratch * g.dNdy.transpose();
  scratch.noalias() = g.dNdx * (g.weight.cwiseProduct(mu)).asDiagonal();
  C.noalias() = scratch * g.dNdx.transpose();
  B.noalias() = scratch * g.dNdy.transpose();
  scratch.noalias() = g.dNdy * (g.weight.cwiseProduct(lambda)).asDiagonal();
  B.noalias() += scratch * g.dNdx.transpose();
  scratch.noalias() = g.dNdy * (g.weight.cwiseProduct(lambda + 2.0 * mu)).asDiagonal();
  C.noalias() += scratch * g.dNdy.transpose();
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
