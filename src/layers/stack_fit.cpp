#include "layers/stack_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "layers/plane_geometry.h"

namespace homesh {
namespace {

using layers_detail::cross;

// Distance along the ray p + s d, s > 0, to segment a b; +infinity if it misses.
// A segment along the ray (the boundary an open wall's end normal slides on)
// is met at its nearer end: the front node cannot slide past a boundary node.
double ray_hit(const Eigen::Vector2d& p, const Eigen::Vector2d& d, const Eigen::Vector2d& a,
               const Eigen::Vector2d& b) {
  const Eigen::Vector2d e = b - a;
  const double den = cross(d, e);
  const double inf = std::numeric_limits<double>::infinity();
  if (std::abs(den) <= 1e-12 * e.norm()) {
    if (std::abs(cross(d, a - p)) > 1e-12 * (a - p).norm()) return inf;
    const double sa = d.dot(a - p), sb = d.dot(b - p);
    const double near = std::min(sa > 0 ? sa : inf, sb > 0 ? sb : inf);
    return near;
  }
  const double s = cross(a - p, e) / den, u = cross(a - p, d) / den;
  return s > 0 && u >= 0 && u <= 1 ? s : inf;
}

}  // namespace

StackFit fit_stack(const Mesh& m, const std::vector<int>& origin, const Eigen::Matrix2Xd& direction,
                   const std::vector<double>& scale, const std::vector<int>& next, double depth,
                   double first, double fill, double cross, double slope) {
  const int lines = static_cast<int>(origin.size());
  StackFit fit;
  fit.factor.assign(lines, 1.0);
  std::vector<double> gap(lines, std::numeric_limits<double>::infinity());
  std::vector<int> curve(lines, -1);
  for (int k = 0; k < lines; ++k) {
    const int w = origin[k];
    const Eigen::Vector2d p = m.x.col(w), d = direction.col(k);
    for (int l = 0; l < m.num_lines(); ++l) {
      const int a = m.line(0, l), b = m.line(1, l);
      if (a == w || b == w) continue;
      const double s = ray_hit(p, d, m.x.col(a), m.x.col(b));
      if (s < gap[k]) {
        gap[k] = s;
        curve[k] = m.line_entity[l];
      }
    }
    const double room = fill * gap[k];
    if (room < first * scale[k] && fit.no_room < 0) {
      fit.no_room = k;
      fit.gap = gap[k];
      fit.curve = curve[k];
    }
    fit.factor[k] = std::min(1.0, room / (depth * scale[k]));
  }
  // Concave walls: consecutive lines k, j converge where the top edge of their
  // cell at depth D, t + D u (t = w_j - w_k, u = s_j n_j - s_k n_k), has no
  // length left along the wall edge: D* = -|t|^2 / (t . u) if t . u < 0. The
  // stack takes `cross` of it on both lines (thinning both by one factor keeps
  // D* over the stack's depth). Fans (lines of one wall node, t = 0) diverge.
  std::vector<bool> crossing(lines, false);
  for (int k = 0; k < lines; ++k) {
    const int j = next[k];
    if (j < 0 || origin[j] == origin[k]) continue;
    const Eigen::Vector2d t = m.x.col(origin[j]) - m.x.col(origin[k]);
    const Eigen::Vector2d u = scale[j] * direction.col(j) - scale[k] * direction.col(k);
    const double tu = t.dot(u);
    if (!(tu < 0)) continue;
    const double cross_depth = -t.squaredNorm() / tu;  // D*, in depth units
    const double limit = std::min(1.0, cross * cross_depth / depth);
    for (const int l : {k, j}) {
      if (limit >= fit.factor[l]) continue;
      fit.factor[l] = limit;
      gap[l] = cross_depth * scale[l];  // along line l, where the neighbours meet
      curve[l] = -1;
      crossing[l] = true;
      if (cross * gap[l] < first * scale[l] && fit.no_room < 0) {
        fit.no_room = l;
        fit.gap = gap[l];
        fit.crossing = true;
      }
    }
  }
  // The thinning spreads to the neighbours: t_k <= t_j + slope |w_k - w_j| / d_n.
  std::vector<int> prev(lines, -1);
  for (int k = 0; k < lines; ++k)
    if (next[k] >= 0) prev[next[k]] = k;
  for (int sweep = 0; sweep < 2; ++sweep)
    for (const std::vector<int>* step : {&next, static_cast<const std::vector<int>*>(&prev)})
      for (int i = 0; i < lines; ++i) {
        const int k = step == &next ? i : lines - 1 - i, j = (*step)[k];
        if (j < 0) continue;
        const double run = (m.x.col(origin[j]) - m.x.col(origin[k])).norm() / depth;
        fit.factor[j] = std::min(fit.factor[j], fit.factor[k] + slope * run);
      }
  // Stretches of thinned lines, each from a line whose predecessor is not thinned.
  std::vector<bool> seen(lines, false);
  for (int k = 0; k < lines; ++k) {
    if (seen[k] || fit.factor[k] >= 1) continue;
    int start = k;
    while (prev[start] >= 0 && fit.factor[prev[start]] < 1 && prev[start] != k) start = prev[start];
    ThinnedStretch t{start,        start,          0, start, fit.factor[start], gap[start],
                     curve[start], crossing[start]};
    for (int j = start; j >= 0 && !seen[j] && fit.factor[j] < 1; j = next[j]) {
      seen[j] = true;
      t.last = j;
      ++t.lines;
      if (fit.factor[j] < t.factor) {
        t.tightest = j;
        t.factor = fit.factor[j];
        t.gap = gap[j];
        t.curve = curve[j];
        t.crossing = crossing[j];
      }
    }
    fit.thinned.push_back(t);
  }
  return fit;
}

}  // namespace homesh
