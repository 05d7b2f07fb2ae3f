#include "quality/jacobian_variation.h"

#include <Eigen/LU>
#include <algorithm>
#include <limits>

namespace homesh {

double jacobian_variation(const ElementSampling& s, const Eigen::Matrix2Xd& X) {
  s.check_nodes(X);
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (int k = 0; k < s.size(); ++k) {
    const double J = s.jacobian(X, k).determinant();
    lo = std::min(lo, J);
    hi = std::max(hi, J);
  }
  if (!(lo > 0.0)) return 0.0;
  return lo / hi;
}

}  // namespace homesh
