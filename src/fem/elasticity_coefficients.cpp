#include "fem/elasticity_coefficients.h"

#include <string>

#include "core/error.h"

namespace homesh {

ScalarCoefficient per_element(Eigen::VectorXd values) {
  return [values = std::move(values)](const QuadraturePoint& q) { return values(q.element); };
}

Lame lame_plane_strain(double young, double poisson) {
  if (!(young > 0.0) || !(poisson > -1.0 && poisson < 0.5))
    throw Error("lame_plane_strain: need E > 0 and -1 < nu < 1/2, got E = " +
                std::to_string(young) + ", nu = " + std::to_string(poisson));
  return {young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson)),
          young / (2.0 * (1.0 + poisson))};
}

}  // namespace homesh
