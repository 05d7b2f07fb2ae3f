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
  return normals;
}

}  // namespace homesh
