#include "fem/element_stiffness.h"

namespace homesh {

Eigen::MatrixXd element_stiffness(const ElementGeometry& g, const Eigen::VectorXd& lambda,
                                  const Eigen::VectorXd& mu) {
  const Eigen::Index n = g.dNdx.rows();
  const Eigen::VectorXd wl = g.weight.cwiseProduct(lambda);
  const Eigen::VectorXd wm = g.weight.cwiseProduct(mu);
  const Eigen::VectorXd wl2m = wl + 2.0 * wm;
  Eigen::MatrixXd K(2 * n, 2 * n);
  // Each block is G1 diag(w c) G2^T summed over the terms of Eq 4.15.
  K.topLeftCorner(n, n).noalias() = g.dNdx * wl2m.asDiagonal() * g.dNdx.transpose();
  K.topLeftCorner(n, n).noalias() += g.dNdy * wm.asDiagonal() * g.dNdy.transpose();
  K.topRightCorner(n, n).noalias() = g.dNdx * wl.asDiagonal() * g.dNdy.transpose();
  K.topRightCorner(n, n).noalias() += g.dNdy * wm.asDiagonal() * g.dNdx.transpose();
  K.bottomRightCorner(n, n).noalias() = g.dNdx * wm.asDiagonal() * g.dNdx.transpose();
  K.bottomRightCorner(n, n).noalias() += g.dNdy * wl2m.asDiagonal() * g.dNdy.transpose();
  K.bottomLeftCorner(n, n) = K.topRightCorner(n, n).transpose();
  // Exactly symmetric (the products above may round A and C asymmetrically).
  Eigen::MatrixXd symmetric = K.selfadjointView<Eigen::Lower>();
  return symmetric;
}

Eigen::MatrixXd element_stiffness(const Eigen::Matrix2Xd& X, const ElementTabulation& tab,
                                  const Eigen::VectorXd& lambda, const Eigen::VectorXd& mu) {
  return element_stiffness(element_geometry(X, tab), lambda, mu);
}

}  // namespace homesh
