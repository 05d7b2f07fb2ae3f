#include "curving/element_distortion.h"

#include <Eigen/LU>
#include <algorithm>

#include "element/lagrange_basis.h"
#include "element/quadrature.h"
#include "element/reference_nodes.h"
#include "quality/ideal_jacobian.h"
#include "quality/shape_measures.h"

namespace homesh {

ElementDistortion element_distortion(const Mesh& m) {
  const int p = m.order, n = m.num_triangles();
  const LagrangeBasis basis(p);
  const Eigen::Matrix2Xd lattice = reference_nodes(2 * p);
  const QuadratureRule rule = triangle_quadrature(2 * (p - 1));
  Eigen::MatrixXd lu, lv, qu, qv;
  basis.tabulate_gradients(lattice, lu, lv);
  basis.tabulate_gradients(rule.points, qu, qv);

  ElementDistortion d;
  d.area.resize(n);
  d.q17_ratio.resize(n);
  d.shape.resize(n);
  for (int e = 0; e < n; ++e) {
    const Eigen::Matrix2Xd X = m.triangle_nodes(e);
    auto jacobian = [&](const Eigen::MatrixXd& du, const Eigen::MatrixXd& dv, Eigen::Index k) {
      Eigen::Matrix2d J;
      J.col(0) = X * du.col(k);
      J.col(1) = X * dv.col(k);
      return J;
    };
    auto det = [&](const Eigen::MatrixXd& du, const Eigen::MatrixXd& dv, Eigen::Index k) {
      return jacobian(du, dv, k).determinant();
    };
    double lo = det(lu, lv, 0), hi = lo, shape = 1.0;
    for (Eigen::Index k = 0; k < lattice.cols(); ++k) {
      const Eigen::Matrix2d J = jacobian(lu, lv, k);
      const double v = J.determinant();
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      shape = std::min(shape, v > 0 ? condition_number_quality(ideal_jacobian(J)) : 0.0);
    }
    d.q17_ratio(e) = hi > 0 ? lo / hi : 0.0;
    d.shape(e) = shape;
    double area = 0;
    for (Eigen::Index k = 0; k < rule.points.cols(); ++k) area += rule.weights(k) * det(qu, qv, k);
    d.area(e) = area;
  }
  return d;
}

}  // namespace homesh
