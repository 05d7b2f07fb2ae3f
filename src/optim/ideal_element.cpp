#include "optim/ideal_element.h"

#include "element/reference_nodes.h"
#include "quality/ideal_jacobian.h"

namespace homesh {

Eigen::Matrix2Xd equilateral_element(int p) {
  return reference_to_ideal_jacobian() * reference_nodes(p);
}

}  // namespace homesh
