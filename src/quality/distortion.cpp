#include "quality/distortion.h"

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "quality/ideal_jacobian.h"

namespace homesh {

double distortion(double q) {
  if (!(q > 0.0)) return std::numeric_limits<double>::infinity();
  return 1.0 / q - 1.0;
}

double distortion_function(const Measure& m, const ElementSampling& rule, const Eigen::Matrix2Xd& X,
                           double r, Reference ref) {
  if (rule.weights().size() != rule.size()) {
    throw Error("distortion function of " + m.name + " needs a quadrature rule with weights");
  }
  if (!(r > 1.0)) {
    throw Error("distortion function exponent r must be > 1, got " + std::to_string(r));
  }
  const ElementScale scale = element_scale(m, rule, X, ref);
  double integral = 0.0;
  double area = 0.0;
  for (int i = 0; i < rule.size(); ++i) {
    const Eigen::Matrix2d J = rule.jacobian(X, i);
    const double theta = distortion(point_quality(m, ideal_jacobian(J), scale, ref));
    if (std::isinf(theta)) return theta;
    const double w_absJ = rule.weights()[i] * std::abs(J.determinant());
    integral += w_absJ * std::pow(theta, r);
    area += w_absJ;
  }
  return std::pow(integral / area, 1.0 / r);
}

}  // namespace homesh
