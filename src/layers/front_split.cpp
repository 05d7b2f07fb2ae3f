#include "layers/front_split.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "layers/plane_geometry.h"

namespace homesh {
namespace {

using layers_detail::ccw_angle;
using layers_detail::cross;
using layers_detail::orient;
using layers_detail::point_text;

int position(const Mesh& m, int e, int v) {
  for (int i = 0; i < 3; ++i)
    if (m.tri(i, e) == v) return i;
  return -1;
}

// The triangles around wall node v counter-clockwise from the wall edge v -> w
// (triangle `first` on its left) to the wall edge u -> v, and the ring nodes
// a_0 = w, ..., a_r = u.
void ring(const Mesh& m, const std::vector<int>& around, int v, int w, int u, int first,
          std::vector<int>& tris, std::vector<int>& nodes) {
  tris.clear();
  nodes = {w};
  int e = first;
  while (true) {
    const int p = position(m, e, v);
    const int b = m.tri((p + 2) % 3, e);
    tris.push_back(e);
    nodes.push_back(b);
    if (b == u) break;
    e = -1;
    for (int f : around)
      if (m.tri((position(m, f, v) + 1) % 3, f) == b) e = f;
    if (e < 0 || tris.size() >= around.size()) break;
  }
  if (nodes.back() != u || tris.size() != around.size())
    throw Error("layers: the triangles at wall node " + std::to_string(v + 1) + " " +
                point_text(m.x.col(v)) +
                " do not fan from one wall edge to the other (does another boundary touch "
                "the wall there?)");
}

struct Fan {
  int node = -1;
  std::vector<Eigen::Vector2d> directions;
  std::vector<int> front;
  double reach = 0;  // distance from the wall node to its nearest opposite edge
};

}  // namespace

FrontSplit split_front(const Mesh& m, const std::vector<WallLoop>& loops,
                       const std::vector<std::vector<WallNormal>>& normals) {
  std::vector<std::vector<int>> around(m.num_nodes());
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int i = 0; i < 3; ++i) around[m.tri(i, e)].push_back(e);

  FrontSplit s;
  s.mesh = m;
  std::vector<Eigen::Vector2d> x;
  std::vector<NodeClass> cls;
  std::vector<std::array<int, 3>> gaps;
  std::vector<int> gap_entity;
  std::vector<Fan> fans;
  const int base = m.num_nodes();
  std::vector<int> tris, nodes;

  for (std::size_t l = 0; l < loops.size(); ++l) {
    const WallLoop& loop = loops[l];
    const int n = loop.size();
    s.front.emplace_back(n);
    for (int i = 0; i < n; ++i) {
      const int v = loop.nodes[i], w = loop.next(i), u = loop.prev(i);
      const WallNormal& normal = normals[l][i];
      const int count = static_cast<int>(normal.directions.size());
      ring(m, around[v], v, w, u, loop.triangles[i], tris, nodes);
      const int surface = m.tri_entity[loop.triangles[i]];
      std::vector<int>& front = s.front[l][i];
      for (int j = 0; j < count; ++j) {
        front.push_back(base + static_cast<int>(x.size()));
        x.push_back(m.x.col(v));
        cls.push_back({2, surface});
      }

      // Groups of ring triangles: triangle q spans ring nodes a_q, a_{q+1}.
      const int r = static_cast<int>(tris.size());
      std::vector<int> split(count, r);  // group j ends before triangle split[j]
      if (count > 1) {
        if (r < 2)
          throw Error("layers: wall node " + point_text(m.x.col(v)) +
                      " has one triangle, too few to split into a fan");
        const Eigen::Vector2d out = m.x.col(w) - m.x.col(v);
        std::vector<double> alpha(r + 1);
        for (int k = 0; k <= r; ++k) alpha[k] = ccw_angle(out, m.x.col(nodes[k]) - m.x.col(v));
        alpha[0] = 0;
        alpha[r] = normal.angle;
        int lo = 1;
        for (int j = 0; j + 1 < count; ++j) {
          const double mid = 0.5 * (ccw_angle(out, normal.directions[j]) +
                                    ccw_angle(out, normal.directions[j + 1]));
          int best = lo;
          for (int k = lo; k <= r - 1; ++k)
            if (std::abs(alpha[k] - mid) < std::abs(alpha[best] - mid)) best = k;
          split[j] = lo = best;
          gaps.push_back({front[j], nodes[best], front[j + 1]});
          gap_entity.push_back(surface);
        }
        Fan fan{v, normal.directions, front, std::numeric_limits<double>::infinity()};
        for (int q = 0; q < r; ++q) {
          const Eigen::Vector2d a = m.x.col(nodes[q]), b = m.x.col(nodes[q + 1]);
          fan.reach = std::min(fan.reach, cross(b - a, m.x.col(v) - a) / (b - a).norm());
        }
        fans.push_back(fan);
      }
      for (int q = 0, j = 0; q < r; ++q) {
        while (q >= split[j]) ++j;
        s.mesh.tri(position(m, tris[q], v), tris[q]) = front[j];
      }
    }
  }

  const int added = static_cast<int>(x.size());
  s.mesh.x.conservativeResize(2, base + added);
  for (int k = 0; k < added; ++k) s.mesh.x.col(base + k) = x[k];
  s.mesh.node_class.insert(s.mesh.node_class.end(), cls.begin(), cls.end());
  s.gap_triangles = static_cast<int>(gaps.size());
  const int t0 = m.num_triangles();
  s.mesh.tri.conservativeResize(3, t0 + s.gap_triangles);
  for (int g = 0; g < s.gap_triangles; ++g)
    for (int i = 0; i < 3; ++i) s.mesh.tri(i, t0 + g) = gaps[g][i];
  s.mesh.tri_entity.insert(s.mesh.tri_entity.end(), gap_entity.begin(), gap_entity.end());
  if (fans.empty()) return s;

  // Fan front nodes a little way along their normals, closer until all is valid.
  for (double c = 0.1; c > 1e-9; c *= 0.5) {
    for (const Fan& f : fans)
      for (std::size_t j = 0; j < f.front.size(); ++j)
        s.mesh.x.col(f.front[j]) = m.x.col(f.node) + c * f.reach * f.directions[j];
    bool valid = true;
    for (int e = 0; e < s.mesh.num_triangles() && valid; ++e)
      valid = orient(s.mesh.x.col(s.mesh.tri(0, e)), s.mesh.x.col(s.mesh.tri(1, e)),
                     s.mesh.x.col(s.mesh.tri(2, e))) > 0;
    if (valid) return s;
  }
  throw Error(
      "layers: the fans of normals cannot be split from the mesh into valid triangles "
      "(at " +
      point_text(m.x.col(fans.front().node)) +
      "...); try fewer normals (fan) or a larger fan_angle");
}

}  // namespace homesh
