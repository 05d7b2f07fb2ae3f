#include "fem/element_load.h"

namespace homesh {

void element_load(const ElementGeometry& g, const Eigen::MatrixXd& N, const Eigen::Matrix2Xd& f,
                  const Eigen::Matrix3Xd& sigma_t, Eigen::VectorXd& fe) {
  const Eigen::Index n = N.rows();
  fe.setZero(2 * n);
  for (Eigen::Index q = 0; q < N.cols(); ++q) {
    const double w = g.weight(q);
    const double sxx = w * sigma_t(0, q), syy = w * sigma_t(1, q), sxy = w * sigma_t(2, q);
    fe.head(n) += (w * f(0, q)) * N.col(q) - sxx * g.dNdx.col(q) - sxy * g.dNdy.col(q);
    fe.tail(n) += (w * f(1, q)) * N.col(q) - sxy * g.dNdx.col(q) - syy * g.dNdy.col(q);
  }
}

Eigen::VectorXd element_load(const ElementGeometry& g, const Eigen::MatrixXd& N,
                             const Eigen::Matrix2Xd& f, const Eigen::Matrix3Xd& sigma_t) {
  Eigen::VectorXd fe;
  element_load(g, N, f, sigma_t, fe);
  return fe;
}

}  // namespace homesh
