#include "curving/interior_blending.h"

#include "element/line_interpolation.h"
#include "element/quad_reference_nodes.h"
#include "element/reference_nodes.h"

namespace homesh {

Eigen::Matrix2Xd blend_interior(const Eigen::Matrix2Xd& X, int p) {
  Eigen::Matrix2Xd out = X;
  if (p < 3) return out;
  const Eigen::Matrix2Xd uv = reference_nodes(p);
  const int n = static_cast<int>(uv.cols());
  // Edge k runs from corner a to corner b (Gmsh: 0-1, 1-2, 2-0); its p - 1 nodes sit at
  // t_j = j / p, j = 1..p-1, from a. q_k(t_j) = deviation / (t_j (1 - t_j)).
  const int corner_a[3] = {0, 1, 2};
  const int corner_b[3] = {1, 2, 0};
  Eigen::Matrix2Xd q[3];
  Eigen::VectorXd t(p - 1);
  for (int j = 1; j < p; ++j) t(j - 1) = j * (1.0 / p);
  for (int k = 0; k < 3; ++k) {
    q[k].resize(2, p - 1);
    const Eigen::Vector2d xa = X.col(corner_a[k]), xb = X.col(corner_b[k]);
    for (int j = 0; j < p - 1; ++j) {
      const Eigen::Vector2d chord = (1 - t(j)) * xa + t(j) * xb;
      q[k].col(j) = (X.col(3 + k * (p - 1) + j) - chord) / (t(j) * (1 - t(j)));
    }
  }
  for (int i = 3 * p; i < n; ++i) {
    const double l[3] = {1 - uv(0, i) - uv(1, i), uv(0, i), uv(1, i)};
    Eigen::Vector2d x = l[0] * X.col(0) + l[1] * X.col(1) + l[2] * X.col(2);
    for (int k = 0; k < 3; ++k) {
      const double la = l[corner_a[k]], lb = l[corner_b[k]];
      x += la * lb * interpolate_on_line(t, q[k], (1 + lb - la) / 2);
    }
    out.col(i) = x;
  }
  return out;
}

// Gordon & Hall 1973: the Coons patch of the four edges, linear blending.
Eigen::Matrix2Xd blend_quad_interior(const Eigen::Matrix2Xd& X, int p) {
  Eigen::Matrix2Xd out = X;
  if (p < 2) return out;
  const Eigen::Matrix2Xd uv = quad_reference_nodes(p);
  Eigen::VectorXd t(p + 1);
  for (int j = 0; j <= p; ++j) t(j) = j * (1.0 / p);
  // d[k]: the deviation of edge k from its chord at t, 0 at both corners.
  Eigen::Matrix2Xd d[4];
  for (int k = 0; k < 4; ++k) {
    d[k] = Eigen::Matrix2Xd::Zero(2, p + 1);
    const Eigen::Vector2d xa = X.col(k), xb = X.col((k + 1) % 4);
    for (int j = 1; j < p; ++j)
      d[k].col(j) = X.col(4 + k * (p - 1) + j - 1) - ((1 - t(j)) * xa + t(j) * xb);
  }
  for (Eigen::Index i = 4 * p; i < uv.cols(); ++i) {
    const double u = uv(0, i), v = uv(1, i);
    out.col(i) = (1 - u) * (1 - v) * X.col(0) + u * (1 - v) * X.col(1) + u * v * X.col(2) +
                 (1 - u) * v * X.col(3) + (1 - v) * interpolate_on_line(t, d[0], u) +
                 u * interpolate_on_line(t, d[1], v) + v * interpolate_on_line(t, d[2], 1 - u) +
                 (1 - u) * interpolate_on_line(t, d[3], 1 - v);
  }
  return out;
}

void blend_interiors(Mesh& m, const std::vector<bool>& moved) {
  const int p = m.order;
  for (int e = 0; e < m.num_quads() && p >= 2; ++e) {
    bool touched = false;
    for (int k = 4; k < 4 * p && !touched; ++k) touched = moved[m.quad(k, e)];
    if (!touched) continue;
    const Eigen::Matrix2Xd X = blend_quad_interior(m.quad_nodes(e), p);
    for (Eigen::Index k = 4 * p; k < m.quad.rows(); ++k) m.x.col(m.quad(k, e)) = X.col(k);
  }
  if (p < 3) return;
  for (int e = 0; e < m.num_triangles(); ++e) {
    bool touched = false;
    for (int k = 3; k < 3 * p && !touched; ++k) touched = moved[m.tri(k, e)];
    if (!touched) continue;
    const Eigen::Matrix2Xd X = blend_interior(m.triangle_nodes(e), p);
    for (Eigen::Index k = 3 * p; k < m.tri.rows(); ++k) m.x.col(m.tri(k, e)) = X.col(k);
  }
}

}  // namespace homesh
