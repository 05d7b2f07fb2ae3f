#include "curving/wall_turn.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "curving/boundary_reconstruction.h"

namespace homesh {
namespace {

constexpr double kSmoothDegrees = 1;  // CAD curves meeting within this are one smooth wall

double degrees(const Eigen::Vector2d& d1, const Eigen::Vector2d& d2) {
  const double cross = d1.x() * d2.y() - d1.y() * d2.x();
  return std::atan2(std::abs(cross), d1.dot(d2)) * 180 / M_PI;
}

}  // namespace

double largest_wall_turn(const Mesh& m, const CurveEvaluator* curves, double corner_degrees) {
  // Up to two lines at each node (a third marks a junction: none counted there).
  std::vector<std::array<int, 3>> at(m.num_nodes(), {-1, -1, -1});
  for (int k = 0; k < m.num_lines(); ++k)
    for (int end = 0; end < 2; ++end) {
      std::array<int, 3>& lines = at[m.line(end, k)];
      *std::find(lines.begin(), lines.end() - 1, -1) = k;  // the last slot: a third line
    }
  const auto other = [&](int k, int v) { return m.line(m.line(0, k) == v ? 1 : 0, k); };
  double largest = 0;
  for (int v = 0; v < m.num_nodes(); ++v) {
    const auto [j, k, third] = at[v];
    if (k < 0 || third >= 0) continue;
    // Along the wall: from j's other end to v, then from v to k's other end.
    const Eigen::Vector2d x = m.x.col(v), in = x - m.x.col(other(j, v)),
                          out = m.x.col(other(k, v)) - x;
    const double turn = degrees(in, out);
    const int a = m.line_entity[j], b = m.line_entity[k];
    const NodeClass& c = m.node_class[v];
    bool smooth;
    if (curves && curves->slides(a) && curves->slides(b)) {
      if (c.dim == 1) {
        smooth = c.tag == a && c.tag == b;
      } else {
        Eigen::Vector2d ta, tb;
        curves->point(a, curves->parameter(a, x), &ta);
        curves->point(b, curves->parameter(b, x), &tb);
        // Each tangent turned the way the wall runs through v.
        if (ta.dot(in) < 0) ta = -ta;
        if (tb.dot(out) < 0) tb = -tb;
        smooth = c.dim == 0 && degrees(ta, tb) < kSmoothDegrees;
      }
    } else {
      smooth = !rebuilt_corner(in, out, a == b, corner_degrees);
    }
    if (smooth) largest = std::max(largest, turn);
  }
  return largest;
}

}  // namespace homesh
