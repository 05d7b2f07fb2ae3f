#pragma once
// The polynomial of degree n - 1 through n points (t_j, y_j) in the plane's
// coordinates, evaluated at s in Lagrange's form: sum_j y_j prod_{i != j} (s - t_i) / (t_j - t_i).
#include <Eigen/Core>

namespace homesh {

/// t: the n distinct abscissae; values: 2 by n ordinates; returns the interpolant at s.
Eigen::Vector2d interpolate_on_line(const Eigen::Ref<const Eigen::VectorXd>& t,
                                    const Eigen::Matrix2Xd& values, double s);

}  // namespace homesh
