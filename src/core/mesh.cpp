#include "core/mesh.h"

#include <algorithm>

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

std::size_t Mesh::triangle_tag(int e) const {
  const std::size_t first = 1 + point_node.size() + static_cast<std::size_t>(num_lines());
  if (num_quads() == 0) return first + static_cast<std::size_t>(e);
  // Before triangle e of surface s: the quadrilaterals of the surfaces before
  // s; before quadrilateral q of s: the triangles of s and of those before it.
  if (e < num_triangles()) {
    const auto quads_before =
        std::lower_bound(quad_entity.begin(), quad_entity.end(), tri_entity[e]) -
        quad_entity.begin();
    return first + static_cast<std::size_t>(e) + static_cast<std::size_t>(quads_before);
  }
  const int q = e - num_triangles();
  const auto triangles_through =
      std::upper_bound(tri_entity.begin(), tri_entity.end(), quad_entity[q]) - tri_entity.begin();
  return first + static_cast<std::size_t>(q) + static_cast<std::size_t>(triangles_through);
}

Eigen::Vector2d Mesh::corner_centroid(int e) const {
  if (e >= num_triangles()) {
    const int q = e - num_triangles();
    return (x.col(quad(0, q)) + x.col(quad(1, q)) + x.col(quad(2, q)) + x.col(quad(3, q))) / 4.0;
  }
  return (x.col(tri(0, e)) + x.col(tri(1, e)) + x.col(tri(2, e))) / 3.0;
}

}  // namespace homesh
