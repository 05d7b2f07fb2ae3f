#include "layers/wall_normals.h"

#include <algorithm>

#include "core/error.h"
#include "layers/plane_geometry.h"

namespace homesh {

using layers_detail::ccw_angle;
using layers_detail::rotate;

WallNormal wall_normal(const Eigen::Vector2d& prev, const Eigen::Vector2d& x,
                       const Eigen::Vector2d& next, const NormalOptions& opt) {
  if (opt.fan < 3 || opt.fan % 2 == 0)
    throw Error("layers: fan must be an odd number of normals >= 3, not " +
                std::to_string(opt.fan));
  if (!(opt.fan_angle >= 180 && opt.fan_angle < 360))
    throw Error("layers: fan_angle must be in [180, 360) degrees");
  if (!(opt.max_scale >= 1)) throw Error("layers: the miter cap max_scale must be >= 1");
  const Eigen::Vector2d out = next - x, in = prev - x;
  if (!(out.norm() > 0 && in.norm() > 0))
    throw Error("layers: a wall edge at " + layers_detail::point_text(x) + " has zero length");
  const Eigen::Vector2d t = out.normalized();
  WallNormal w;
  w.angle = ccw_angle(out, in);
  if (w.angle <= 0) w.angle = 2 * M_PI;
  if (opt.multi && w.angle >= opt.fan_angle * M_PI / 180) {
    for (int j = 0; j < opt.fan; ++j)
      w.directions.push_back(rotate(t, M_PI / 2 + (w.angle - M_PI) * j / (opt.fan - 1)));
    w.scale = 1;
  } else {
    w.directions.push_back(rotate(t, w.angle / 2));
    w.scale = std::min(1 / std::sin(w.angle / 2), opt.max_scale);
  }
  return w;
}

WallNormal wall_end_normal(const Eigen::Vector2d& side, const Eigen::Vector2d& x,
                           const Eigen::Vector2d& wall, bool start, const NormalOptions& opt) {
  NormalOptions single = opt;
  single.multi = false;
  WallNormal w = start ? wall_normal(side, x, wall, single) : wall_normal(wall, x, side, single);
  if (!(w.angle < opt.max_end_angle * M_PI / 180))
    throw Error("layers: the open wall ends at " + layers_detail::point_text(x) +
                " at a domain angle of " + layers_detail::number_text(w.angle * 180 / M_PI) +
                " deg to the next boundary, not below max_end_angle = " +
                layers_detail::number_text(opt.max_end_angle) +
                " deg, so its layers cannot end along that boundary");
  w.directions = {(side - x).normalized()};
  w.scale = std::min(1 / std::sin(w.angle), opt.max_scale);
  return w;
}

void blend_normals(const Mesh& m, const WallLoop& loop, std::vector<WallNormal>& normals,
                   int sweeps, double max_scale) {
  const int n = loop.size();
  const double limit = M_PI / 6;
  // Where the wall turns fast: a node whose edges, or a neighbour's, turn by
  // more than `limit` (30 deg, the corpus' line between smooth and fast walls).
  // A node on a CAD point (node class dim 0) whose neighbours' edges turn by less
  // than 10 deg is a corner of the geometry (a box's, a trailing edge), kept
  // sharp; on a point where the wall turns fast on both sides too (the joint of
  // two splines at a coarse nose), the wall is smooth and under-resolved.
  std::vector<bool> fast(n, false);
  auto turn = [&](int i) { return std::abs(normals[i].angle - M_PI); };
  auto corner = [&](int i) {
    const int v = loop.nodes[i];
    if (!(v < static_cast<int>(m.node_class.size()) && m.node_class[v].dim == 0)) return false;
    for (int j : {i - 1, i + 1})
      if ((loop.closed || (j >= 0 && j < n)) && turn((j + n) % n) >= limit / 3) return false;
    return true;
  };
  for (int i = 0; i < n; ++i)
    if (turn(i) > limit && !corner(i))
      for (int j : {i - 1, i, i + 1})
        if (loop.closed || (j >= 0 && j < n)) fast[(j + n) % n] = true;
  auto single = [&](int i) {
    return fast[i] && normals[i].directions.size() == 1 && (loop.closed || (i > 0 && i < n - 1));
  };
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    std::vector<Eigen::Vector2d> blended(n);
    for (int i = 0; i < n; ++i) {
      if (!single(i)) continue;
      // The prev node's normal on the edge prev -> i, its outgoing edge (a fan's
      // first); the next node's on i -> next, its incoming edge (a fan's last).
      // (A blended node has both: open ends are not blended.)
      blended[i] = (2 * normals[i].directions[0] + normals[(i + n - 1) % n].directions.front() +
                    normals[(i + 1) % n].directions.back())
                       .normalized();
    }
    for (int i = 0; i < n; ++i) {
      if (!single(i)) continue;
      const Eigen::Vector2d x = m.x.col(loop.nodes[i]);
      const Eigen::Vector2d t = (m.x.col(loop.next(i)) - x).normalized();
      const double theta = normals[i].angle;
      double phi = ccw_angle(t, blended[i]);
      if (phi < 0) phi += 2 * M_PI;
      const double lo = std::max(theta / 2 - limit, std::min(limit, theta / 2)),
                   hi = std::min(theta / 2 + limit, std::max(theta - limit, theta / 2));
      phi = std::clamp(phi, lo, hi);
      normals[i].directions[0] = rotate(t, phi);
      // The depth kept from both edges' lines, as wall_normal's miter on the bisector.
      const double sine = std::min(std::sin(phi), std::sin(theta - phi));
      normals[i].scale = sine > 1 / max_scale ? 1 / sine : max_scale;
    }
  }
}

std::vector<WallNormal> wall_normals(const Mesh& m, const WallLoop& loop,
                                     const NormalOptions& opt) {
  const int n = loop.size();
  std::vector<WallNormal> normals;
  normals.reserve(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d prev = m.x.col(loop.prev(i)), x = m.x.col(loop.nodes[i]),
                          next = m.x.col(loop.next(i));
    if (!loop.closed && i == 0)
      normals.push_back(wall_end_normal(prev, x, next, true, opt));
    else if (!loop.closed && i == n - 1)
      normals.push_back(wall_end_normal(next, x, prev, false, opt));
    else
      normals.push_back(wall_normal(prev, x, next, opt));
  }
  if (opt.blend > 0) blend_normals(m, loop, normals, opt.blend, opt.max_scale);
  return normals;
}

}  // namespace homesh
