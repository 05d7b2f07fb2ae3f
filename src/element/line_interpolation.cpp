#include "element/line_interpolation.h"

namespace homesh {

Eigen::Vector2d interpolate_on_line(const Eigen::Ref<const Eigen::VectorXd>& t,
                                    const Eigen::Matrix2Xd& values, double s) {
  Eigen::Vector2d v = Eigen::Vector2d::Zero();
  for (Eigen::Index j = 0; j < t.size(); ++j) {
    double w = 1;
    for (Eigen::Index i = 0; i < t.size(); ++i)
      if (i != j) w *= (s - t(i)) / (t(j) - t(i));
    v += w * values.col(j);
  }
  return v;
}

}  // namespace homesh
