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

std::vector<WallNormal> wall_normals(const Mesh& m, const WallLoop& loop,
                                     const NormalOptions& opt) {
  const int n = static_cast<int>(loop.nodes.size());
  std::vector<WallNormal> normals;
  normals.reserve(n);
  for (int i = 0; i < n; ++i)
    normals.push_back(wall_normal(m.x.col(loop.nodes[(i + n - 1) % n]), m.x.col(loop.nodes[i]),
                                  m.x.col(loop.nodes[(i + 1) % n]), opt));
  return normals;
}

}  // namespace homesh
