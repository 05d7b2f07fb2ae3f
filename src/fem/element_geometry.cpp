#include "fem/element_geometry.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace homesh {

ElementGeometry element_geometry(const Eigen::Matrix2Xd& X, const ElementTabulation& tab) {
  ElementGeometry g;
  element_geometry(X, tab, g);
  return g;
}

void element_geometry(const Eigen::Matrix2Xd& X, const ElementTabulation& tab, ElementGeometry& g) {
  if (X.cols() != tab.N.rows())
    throw Error("element_geometry: " + std::to_string(X.cols()) + " nodes for a " +
                (tab.quad ? "quadrilateral" : "triangle") + " of order " +
                std::to_string(tab.order));
  const Eigen::Index n = tab.N.rows(), nq = tab.N.cols();
  g.x.resize(2, nq);
  g.dNdx.resize(n, nq);
  g.dNdy.resize(n, nq);
  g.weight.resize(nq);
  double det_min = INFINITY, det_max = -INFINITY;
  for (Eigen::Index q = 0; q < nq; ++q) {
    // Columns of J: (dx/du, dy/du) and (dx/dv, dy/dv).
    const Eigen::Vector2d ju = X * tab.dNdu.col(q);
    const Eigen::Vector2d jv = X * tab.dNdv.col(q);
    const double det = ju(0) * jv(1) - jv(0) * ju(1);
    det_min = std::min(det_min, det);
    det_max = std::max(det_max, det);
    // J^-T = [dy/dv, -dy/du; -dx/dv, dx/du] / det J.
    const double a = jv(1) / det, b = ju(1) / det, c = jv(0) / det, d = ju(0) / det;
    g.dNdx.col(q) = a * tab.dNdu.col(q) - b * tab.dNdv.col(q);
    g.dNdy.col(q) = d * tab.dNdv.col(q) - c * tab.dNdu.col(q);
    g.weight(q) = tab.rule.weights(q) * std::abs(det);
    g.x.col(q) = X * tab.N.col(q);
  }
  if (!(det_min > 0.0) && !(det_max < 0.0))
    throw Error("element_geometry: det J changes sign or vanishes (min " + std::to_string(det_min) +
                ", max " + std::to_string(det_max) + ")");
}

}  // namespace homesh
