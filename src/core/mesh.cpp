#include "core/mesh.h"

namespace homesh {

Eigen::Matrix2Xd Mesh::triangle_nodes(int e) const {
  Eigen::Matrix2Xd X(2, tri.rows());
  for (int i = 0; i < tri.rows(); ++i) X.col(i) = x.col(tri(i, e));
  return X;
}

Eigen::Matrix2Xd Mesh::quad_nodes(int e) const {
  Eigen::Matrix2Xd X(2, quad.rows());
  for (int i = 0; i < quad.rows(); ++i) X.col(i) = x.col(quad(i, e));
  return X;
}

Eigen::Vector2d Mesh::corner_centroid(int e) const {
  if (e >= num_triangles()) {
    const int q = e - num_triangles();
    return (x.col(quad(0, q)) + x.col(quad(1, q)) + x.col(quad(2, q)) + x.col(quad(3, q))) / 4.0;
  }
  return (x.col(tri(0, e)) + x.col(tri(1, e)) + x.col(tri(2, e))) / 3.0;
}

}  // namespace homesh
