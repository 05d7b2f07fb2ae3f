#include "core/mesh.h"

namespace homesh {

Eigen::Matrix2Xd Mesh::triangle_nodes(int e) const {
  Eigen::Matrix2Xd X(2, tri.rows());
  for (int i = 0; i < tri.rows(); ++i) X.col(i) = x.col(tri(i, e));
  return X;
}

Eigen::Vector2d Mesh::corner_centroid(int e) const {
  return (x.col(tri(0, e)) + x.col(tri(1, e)) + x.col(tri(2, e))) / 3.0;
}

}  // namespace homesh
