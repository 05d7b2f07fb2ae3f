#include "core/mesh.h"

namespace homesh {

Eigen::Matrix2Xd Mesh::triangle_nodes(int e) const {
  Eigen::Matrix2Xd X(2, tri.rows());
  for (int i = 0; i < tri.rows(); ++i) X.col(i) = x.col(tri(i, e));
  return X;
}

}  // namespace homesh
