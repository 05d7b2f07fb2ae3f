#include "element/square_quadrature.h"

#include <string>

#include "core/error.h"

namespace homesh {

QuadratureRule square_quadrature(int degree) {
  if (degree < 0) throw Error("square_quadrature: degree " + std::to_string(degree) + " < 0");
  const LineQuadratureRule line = line_quadrature(degree);
  const Eigen::Index n = line.points.size();
  QuadratureRule rule;
  rule.points.resize(2, n * n);
  rule.weights.resize(n * n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i) {
      rule.points.col(i + n * j) << line.points(i), line.points(j);
      rule.weights(i + n * j) = line.weights(i) * line.weights(j);
    }
  return rule;
}

}  // namespace homesh
