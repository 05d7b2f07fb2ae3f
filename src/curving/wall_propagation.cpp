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
  // The lines by cell (CSR, ascending k per cell) over the cells holding a line's
  // midpoint: a grid of their bounding box where it is small (the usual case: cells are
  // 1.5 wall lines long at least), else a hash map of the cells that hold lines.
  std::vector<std::pair<long, long>> cell_of(lines.size());
  long i0 = std::numeric_limits<long>::max(), i1 = std::numeric_limits<long>::min();
  long j0 = i0, j1 = i1;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    cell_of[k] = key((lines[k].a + lines[k].b) / 2);
    i0 = std::min(i0, cell_of[k].first);
    i1 = std::max(i1, cell_of[k].first);
    j0 = std::min(j0, cell_of[k].second);
    j1 = std::max(j1, cell_of[k].second);
  }
  const long ni = i1 - i0 + 1, nj = j1 - j0 + 1;
  const bool dense = ni * nj <= 16 * static_cast<long>(lines.size()) + 4096;
  auto hash = [](long i, long j) { return static_cast<long long>(i) * 1000003LL + j; };
  std::vector<int> start, member;  // dense: cell (i, j) holds member[start[c] .. start[c + 1])
  std::unordered_map<long long, std::vector<int>> buckets;
  if (dense) {
    start.assign(ni * nj + 1, 0);
    for (const auto& [i, j] : cell_of) ++start[(i - i0) * nj + (j - j0) + 1];
    for (long c = 0; c < ni * nj; ++c) start[c + 1] += start[c];
    member.resize(lines.size());
    std::vector<int> next(start.begin(), start.end() - 1);
    for (int k = 0; k < static_cast<int>(lines.size()); ++k)
      member[next[(cell_of[k].first - i0) * nj + (cell_of[k].second - j0)]++] = k;
  } else {
    for (int k = 0; k < static_cast<int>(lines.size()); ++k)
      buckets[hash(cell_of[k].first, cell_of[k].second)].push_back(k);
  }
  for (int n = 0; n < m.num_nodes(); ++n) {
    if (!free[n]) continue;
    const Eigen::Vector2d x = m.x.col(n);
    const auto [ci, cj] = key(x);
    // No line's cell within one of the node's: nothing in reach.
    if (ci < i0 - 1 || ci > i1 + 1 || cj < j0 - 1 || cj > j1 + 1) continue;
    double best = std::numeric_limits<double>::infinity();
    int best_line = -1;
    double best_t = 0;
    auto consider = [&](int k) {
      const WallLine& w = lines[k];
      const Eigen::Vector2d e = w.b - w.a;
      const double t = std::clamp((x - w.a).dot(e) / e.squaredNorm(), 0.0, 1.0);
      const double s = (x - (w.a + t * e)).norm();
      if (s < best) {
        best = s;
        best_line = k;
        best_t = t;
      }
    };
    for (long i = std::max(ci - 1, i0); i <= std::min(ci + 1, i1); ++i)
      for (long j = std::max(cj - 1, j0); j <= std::min(cj + 1, j1); ++j) {
        if (dense) {
          const long c = (i - i0) * nj + (j - j0);
          for (int a = start[c]; a < start[c + 1]; ++a) consider(member[a]);
        } else if (const auto it = buckets.find(hash(i, j)); it != buckets.end()) {
          for (int k : it->second) consider(k);
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
