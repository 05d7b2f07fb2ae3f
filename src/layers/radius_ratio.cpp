#include "layers/radius_ratio.h"

#include <algorithm>

namespace homesh {

double radius_ratio(const Eigen::Matrix<double, 2, 3>& X) {
  const double a = (X.col(1) - X.col(2)).norm();
  const double b = (X.col(2) - X.col(0)).norm();
  const double c = (X.col(0) - X.col(1)).norm();
  const double abc = a * b * c;
  if (!(abc > 0)) return 0.0;
  const double p = 0.5 * (a + b + c);
  // Rounding can make p - a slightly negative for a degenerate triangle.
  return std::max(0.0, 8 * (p - a) * (p - b) * (p - c) / abc);
}

Eigen::VectorXd radius_ratios(const Mesh& m) {
  Eigen::VectorXd q(m.num_elements_2d());
  for (int e = 0; e < m.num_triangles(); ++e) {
    Eigen::Matrix<double, 2, 3> X;
    for (int i = 0; i < 3; ++i) X.col(i) = m.x.col(m.tri(i, e));
    q(e) = radius_ratio(X);
  }
  for (int e = 0; e < m.num_quads(); ++e) {
    double worst = 1;
    for (int c = 0; c < 4; ++c) {
      Eigen::Matrix<double, 2, 3> X;
      for (int i = 0; i < 3; ++i) X.col(i) = m.x.col(m.quad((c + 3 + i) % 4, e));
      const Eigen::Vector2d a = X.col(1) - X.col(0), b = X.col(2) - X.col(1);
      worst = std::min(worst, a(0) * b(1) - a(1) * b(0) > 0 ? radius_ratio(X) : 0.0);
    }
    q(m.num_triangles() + e) = worst;
  }
  return q;
}

}  // namespace homesh
