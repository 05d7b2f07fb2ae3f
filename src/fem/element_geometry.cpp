#include "fem/element_geometry.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace homesh {

ElementGeometry element_geometry(const Eigen::Matrix2Xd& X, const ElementTabulation& tab) {
  if (X.cols() != tab.N.rows())
    throw Error("element_geometry: " + std::to_string(X.cols()) + " nodes for order " +
                std::to_string(tab.order));
  // Columns of J at every point: (dx/du, dy/du) and (dx/dv, dy/dv).
  const Eigen::Matrix2Xd Ju = X * tab.dNdu;
  const Eigen::Matrix2Xd Jv = X * tab.dNdv;
  const Eigen::ArrayXd det = Ju.row(0).array() * Jv.row(1).array() -
                             Jv.row(0).array() * Ju.row(1).array();
  const bool positive = det.minCoeff() > 0.0;
  if (!positive && !(det.maxCoeff() < 0.0))
    throw Error("element_geometry: det J changes sign or vanishes (min " +
                std::to_string(det.minCoeff()) + ", max " + std::to_string(det.maxCoeff()) +
                ")");
  // J^-T = [dy/dv, -dy/du; -dx/dv, dx/du] / det J.
  const Eigen::ArrayXd a = Jv.row(1).transpose().array() / det;
  const Eigen::ArrayXd b = Ju.row(1).transpose().array() / det;
  const Eigen::ArrayXd c = Jv.row(0).transpose().array() / det;
  const Eigen::ArrayXd d = Ju.row(0).transpose().array() / det;
  ElementGeometry g;
  g.x = X * tab.N;
  g.dNdx = tab.dNdu * a.matrix().asDiagonal();
  g.dNdx -= tab.dNdv * b.matrix().asDiagonal();
  g.dNdy = tab.dNdv * d.matrix().asDiagonal();
  g.dNdy -= tab.dNdu * c.matrix().asDiagonal();
  g.weight = (tab.rule.weights.array() * det.abs()).matrix();
  return g;
}

}  // namespace homesh
