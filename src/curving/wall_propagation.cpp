#include "curving/wall_propagation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "element/line_interpolation.h"
#include "element/reference_nodes.h"

namespace homesh {
namespace {

struct WallLine {
  Eigen::Vector2d a, b;  // chord ends
  Eigen::Matrix2Xd dev;  // deviation at the p + 1 nodes, Gmsh line order
  double length = 0;
};

}  // namespace

Eigen::Matrix2Xd propagate_wall_displacement(const Mesh& m, const Eigen::Matrix2Xd& target,
                                             const std::vector<bool>& free, double radius) {
  Eigen::Matrix2Xd u = Eigen::Matrix2Xd::Zero(2, m.num_nodes());
  const int p = m.order;
  const Eigen::VectorXd tn = reference_line_nodes(p).transpose();
  std::vector<WallLine> lines;
  for (int l = 0; l < m.num_lines(); ++l) {
    WallLine w;
    w.a = m.x.col(m.line(0, l));
    w.b = m.x.col(m.line(1, l));
    w.length = (w.b - w.a).norm();
    w.dev.resize(2, p + 1);
    for (int k = 0; k <= p; ++k) w.dev.col(k) = target.col(m.line(k, l)) - m.x.col(m.line(k, l));
    if (w.length > 0 && w.dev.cwiseAbs().maxCoeff() > 1e-14 * w.length)
      lines.push_back(std::move(w));
  }
  if (lines.empty() || radius <= 0) return u;
  // Buckets of side the longest reach: a node's candidates are in its 3 x 3 cells.
  double cell = 0;
  for (const WallLine& w : lines) cell = std::max(cell, (radius + 0.5) * w.length);
  Eigen::Vector2d lo = m.x.rowwise().minCoeff();
  auto key = [&](const Eigen::Vector2d& x) {
    const long i = static_cast<long>(std::floor((x(0) - lo(0)) / cell));
    const long j = static_cast<long>(std::floor((x(1) - lo(1)) / cell));
    return std::make_pair(i, j);
  };
  auto hash = [](long i, long j) { return static_cast<long long>(i) * 1000003LL + j; };
  std::unordered_map<long long, std::vector<int>> buckets;
  for (int k = 0; k < static_cast<int>(lines.size()); ++k) {
    const Eigen::Vector2d mid = (lines[k].a + lines[k].b) / 2;
    const auto [i, j] = key(mid);
    buckets[hash(i, j)].push_back(k);
  }
  for (int n = 0; n < m.num_nodes(); ++n) {
    if (!free[n]) continue;
    const Eigen::Vector2d x = m.x.col(n);
    const auto [ci, cj] = key(x);
    double best = std::numeric_limits<double>::infinity();
    int best_line = -1;
    double best_t = 0;
    for (long i = ci - 1; i <= ci + 1; ++i)
      for (long j = cj - 1; j <= cj + 1; ++j) {
        const auto it = buckets.find(hash(i, j));
        if (it == buckets.end()) continue;
        for (int k : it->second) {
          const WallLine& w = lines[k];
          const Eigen::Vector2d e = w.b - w.a;
          const double t = std::clamp((x - w.a).dot(e) / e.squaredNorm(), 0.0, 1.0);
          const double s = (x - (w.a + t * e)).norm();
          if (s < best) {
            best = s;
            best_line = k;
            best_t = t;
          }
        }
      }
    if (best_line < 0) continue;
    const WallLine& w = lines[best_line];
    const double r = best / (radius * w.length);
    if (r >= 1) continue;
    u.col(n) = (1 - 3 * r * r + 2 * r * r * r) * interpolate_on_line(tn, w.dev, best_t);
  }
  return u;
}

}  // namespace homesh
