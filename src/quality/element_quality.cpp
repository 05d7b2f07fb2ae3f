#include "quality/element_quality.h"

#include <Eigen/LU>
#include <algorithm>

#include "quality/ideal_jacobian.h"

namespace homesh {

ElementScale element_scale(const Measure& m, const ElementSampling& s, const Eigen::Matrix2Xd& X,
                           Reference ref) {
  s.check_nodes(X);
  ElementScale scale;
  if (!m.pointwise()) {
    scale.element_value = m.element(s, X);
  } else if (ref == Reference::element_max && m.thesis_max_normalised) {
    for (int k = 0; k < s.size(); ++k) {
      const Eigen::Matrix2d W = ideal_jacobian(s.jacobian(X, k));
      if (W.determinant() > 0.0) scale.max_raw = std::max(scale.max_raw, m.raw(W));
    }
  }
  return scale;
}

double point_quality(const Measure& m, const Eigen::Matrix2d& W, const ElementScale& scale,
                     Reference ref) {
  if (!m.pointwise()) return scale.element_value;
  if (ref == Reference::element_max && m.thesis_max_normalised) {
    if (W.determinant() <= 0.0 || !(scale.max_raw > 0.0)) return 0.0;
    return m.raw(W) / scale.max_raw;
  }
  return m.quality(W);
}

ElementQuality element_quality(const Measure& m, const ElementSampling& s,
                               const Eigen::Matrix2Xd& X, Reference ref) {
  const ElementScale scale = element_scale(m, s, X, ref);
  ElementQuality result;
  result.values.resize(s.size());
  for (int k = 0; k < s.size(); ++k) {
    result.values[k] = point_quality(m, ideal_jacobian(s.jacobian(X, k)), scale, ref);
  }
  result.min = s.size() > 0 ? result.values.minCoeff() : 0.0;
  return result;
}

ElementQuality element_quality(const Measure& m, const Eigen::Matrix2Xd& X, int p,
                               const Eigen::Matrix2Xd& uv, Reference ref) {
  return element_quality(m, ElementSampling(p, uv), X, ref);
}

}  // namespace homesh
