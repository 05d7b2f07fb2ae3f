#include "fem/element_load.h"

namespace homesh {

Eigen::VectorXd element_load(const ElementGeometry& g, const Eigen::MatrixXd& N,
                             const Eigen::Matrix2Xd& f, const Eigen::Matrix3Xd& sigma_t) {
  const Eigen::Index n = N.rows();
  const Eigen::ArrayXd w = g.weight.array();
  const Eigen::VectorXd sxx = (w * sigma_t.row(0).transpose().array()).matrix();
  const Eigen::VectorXd syy = (w * sigma_t.row(1).transpose().array()).matrix();
  const Eigen::VectorXd sxy = (w * sigma_t.row(2).transpose().array()).matrix();
  Eigen::VectorXd fe(2 * n);
  fe.head(n) = N * (w * f.row(0).transpose().array()).matrix() - g.dNdx * sxx - g.dNdy * sxy;
  fe.tail(n) = N * (w * f.row(1).transpose().array()).matrix() - g.dNdx * sxy - g.dNdy * syy;
  return fe;
}

}  // namespace homesh
