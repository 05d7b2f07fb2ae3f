#pragma once
// Small linear meshes for the boundary-layer tests, built without Gmsh: a
// structured O-mesh between two closed loops and a square-cell grid, which
// classify walls on curve 1 (physical "wall"), the other boundary on curve 2
// (physical "outer"), and a four-sided channel (curves "wall", "outlet", "top",
// "inlet"). All put the triangles on surface 1 (physical "fluid") and list them
// counter-clockwise.
#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh.h"
#include "layers/insert_layers.h"

namespace homesh::test {

/// Layer options: n layers on `walls`, first depth `first`, growth `ratio`.
inline LayerOptions layer_options(std::vector<std::string> walls, int n, double first,
                                  double ratio) {
  LayerOptions o;
  o.walls = std::move(walls);
  o.layers = n;
  o.first = first;
  o.ratio = ratio;
  return o;
}

inline void set_groups(Mesh& m) {
  m.entities = {{1, 1, {}}, {1, 2, {}}, {2, 1, {1, 2}}};
  m.physicals = {{1, 10, "wall", {1}}, {1, 11, "outer", {2}}, {2, 12, "fluid", {1}}};
}

inline void add_triangle(Mesh& m, int e, int a, int b, int c) {
  const Eigen::Vector2d pa = m.x.col(a), pb = m.x.col(b), pc = m.x.col(c);
  const double s = (pb - pa)(0) * (pc - pa)(1) - (pb - pa)(1) * (pc - pa)(0);
  m.tri.col(e) << a, (s > 0 ? b : c), (s > 0 ? c : b);
}

/// O-mesh between the closed loops `inner` (curve 1) and `outer` (curve 2), both
/// 2 by N with matching points: node (i, k) = (1 - t) inner_i + t outer_i with
/// t = (k / rings)^grading, quads split into two triangles.
inline Mesh ring_mesh(const Eigen::Matrix2Xd& inner, const Eigen::Matrix2Xd& outer, int rings,
                      double grading = 1) {
  const int n = static_cast<int>(inner.cols());
  Mesh m;
  m.x.resize(2, n * (rings + 1));
  for (int k = 0; k <= rings; ++k) {
    const double t = std::pow(static_cast<double>(k) / rings, grading);
    for (int i = 0; i < n; ++i) {
      m.x.col(k * n + i) = (1 - t) * inner.col(i) + t * outer.col(i);
      NodeClass c{2, 1};
      if (k == 0) c = {1, 1, static_cast<double>(i)};
      if (k == rings) c = {1, 2, static_cast<double>(i)};
      m.node_class.push_back(c);
    }
  }
  m.tri.resize(3, 2 * n * rings);
  for (int k = 0; k < rings; ++k)
    for (int i = 0; i < n; ++i) {
      const int a = k * n + i, b = k * n + (i + 1) % n, c = a + n, d = b + n;
      add_triangle(m, 2 * (k * n + i), a, b, d);
      add_triangle(m, 2 * (k * n + i) + 1, a, d, c);
    }
  m.tri_entity.assign(m.tri.cols(), 1);
  m.line.resize(2, 2 * n);
  for (int i = 0; i < n; ++i) {
    m.line.col(i) << i, (i + 1) % n;
    m.line.col(n + i) << rings * n + i, rings * n + (i + 1) % n;
    m.line_entity.push_back(1);
  }
  m.line_entity.resize(2 * n, 2);
  set_groups(m);
  return m;
}

/// N points on the circle of radius r about c, counter-clockwise from angle 0.
inline Eigen::Matrix2Xd circle(int n, double r,
                               const Eigen::Vector2d& c = Eigen::Vector2d::Zero()) {
  Eigen::Matrix2Xd p(2, n);
  for (int i = 0; i < n; ++i)
    p.col(i) = c + r * Eigen::Vector2d(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n));
  return p;
}

/// 4 k points on the rhombus with tips (+-1, 0) and (0, +-half_width),
/// counter-clockwise from the tip (1, 0); its sharp tips have the interior
/// angle 2 atan(half_width).
inline Eigen::Matrix2Xd rhombus(int k, double half_width) {
  const Eigen::Vector2d v[4] = {{1, 0}, {0, half_width}, {-1, 0}, {0, -half_width}};
  Eigen::Matrix2Xd p(2, 4 * k);
  for (int s = 0; s < 4; ++s)
    for (int i = 0; i < k; ++i)
      p.col(s * k + i) = v[s] + (v[(s + 1) % 4] - v[s]) * static_cast<double>(i) / k;
  return p;
}

/// Cells (i, j) of an nx by ny grid of spacing h with keep(i, j), each split
/// into two triangles; boundary edges on curve 1 where on_wall(midpoint), else 2.
inline Mesh grid_mesh(int nx, int ny, double h, const std::function<bool(int, int)>& keep,
                      const std::function<bool(const Eigen::Vector2d&)>& on_wall) {
  auto kept = [&](int i, int j) { return i >= 0 && j >= 0 && i < nx && j < ny && keep(i, j); };
  std::map<std::pair<int, int>, int> index;
  Mesh m;
  auto node = [&](int i, int j) {
    const auto it = index.find({i, j});
    if (it != index.end()) return it->second;
    const int id = static_cast<int>(index.size());
    index[{i, j}] = id;
    m.x.conservativeResize(2, id + 1);
    m.x.col(id) = Eigen::Vector2d(i * h, j * h);
    m.node_class.push_back({2, 1});
    return id;
  };
  std::vector<Eigen::Vector3i> tris;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (!kept(i, j)) continue;
      const int a = node(i, j), b = node(i + 1, j), c = node(i + 1, j + 1), d = node(i, j + 1);
      tris.emplace_back(a, b, c);
      tris.emplace_back(a, c, d);
      // Boundary edges, counter-clockwise around the cell.
      const std::pair<int, int> ends[4] = {{a, b}, {b, c}, {c, d}, {d, a}};
      const bool open[4] = {!kept(i, j - 1), !kept(i + 1, j), !kept(i, j + 1), !kept(i - 1, j)};
      for (int s = 0; s < 4; ++s) {
        if (!open[s]) continue;
        const auto [p, q] = ends[s];
        const int tag = on_wall(0.5 * (m.x.col(p) + m.x.col(q))) ? 1 : 2;
        m.line.conservativeResize(2, m.line.cols() + 1);
        m.line.col(m.line.cols() - 1) << p, q;
        m.line_entity.push_back(tag);
        m.node_class[p] = m.node_class[q] = {1, tag};
      }
    }
  m.tri.resize(3, static_cast<int>(tris.size()));
  for (std::size_t e = 0; e < tris.size(); ++e) m.tri.col(e) = tris[e];
  m.tri_entity.assign(tris.size(), 1);
  set_groups(m);
  return m;
}

/// A structured nx by ny channel on the image of the unit square under
/// map(s, t) (orientation-preserving, straight sides), each cell split into two
/// triangles. Curves, counter-clockwise, with parameter u = arc length from
/// their first corner: 1 bottom t = 0 ("wall"), 2 right s = 1 ("outlet"), 3 top
/// t = 1 ("top"), 4 left s = 0 ("inlet"); points 1-4 at the corners (0, 0),
/// (1, 0), (1, 1), (0, 1) of the square. Node (i, j) is j (nx + 1) + i.
inline Mesh channel_mesh(int nx, int ny,
                         const std::function<Eigen::Vector2d(double, double)>& map) {
  Mesh m;
  const int w = nx + 1;
  m.x.resize(2, w * (ny + 1));
  m.node_class.assign(m.x.cols(), {2, 1});
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.x.col(j * w + i) = map(double(i) / nx, double(j) / ny);
  m.tri.resize(3, 2 * nx * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * w + i, b = a + 1, c = b + w, d = a + w;
      m.tri.col(2 * (j * nx + i)) << a, b, c;
      m.tri.col(2 * (j * nx + i) + 1) << a, c, d;
    }
  m.tri_entity.assign(m.tri.cols(), 1);
  // The sides from corner to corner: (first node, step, count of lines).
  const int side[4][3] = {{0, 1, nx}, {nx, w, ny}, {w * (ny + 1) - 1, -1, nx}, {ny * w, -w, ny}};
  for (int c = 0; c < 4; ++c) {
    const auto [first, step, count] = side[c];
    double u = 0;
    for (int k = 0; k < count; ++k) {
      const int a = first + k * step, b = a + step;
      m.line.conservativeResize(2, m.line.cols() + 1);
      m.line.col(m.line.cols() - 1) << a, b;
      m.line_entity.push_back(c + 1);
      if (k > 0) m.node_class[a] = {1, c + 1, u};
      u += (m.x.col(b) - m.x.col(a)).norm();
    }
    m.node_class[first] = {0, c + 1};
    m.point_node.push_back(first);
    m.point_entity.push_back(c + 1);
  }
  m.entities = {{0, 1, {}},      {0, 2, {}},      {0, 3, {}},
                {0, 4, {}},      {1, 1, {1, -2}}, {1, 2, {2, -3}},
                {1, 3, {3, -4}}, {1, 4, {4, -1}}, {2, 1, {1, 2, 3, 4}}};
  m.physicals = {{1, 10, "wall", {1}},
                 {1, 11, "outlet", {2}},
                 {1, 12, "top", {3}},
                 {1, 13, "inlet", {4}},
                 {2, 14, "fluid", {1}}};
  return m;
}

}  // namespace homesh::test
