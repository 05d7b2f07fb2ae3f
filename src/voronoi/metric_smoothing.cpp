#include "voronoi/metric_smoothing.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace homesh {
namespace {

constexpr double kPoor = 0.8;     // below this worst quality, the compass search too
constexpr int kSearchSteps = 24;  // its steps

}  // namespace

double metric_mean_ratio(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                         const Eigen::Vector2d& c, const Eigen::Matrix2d& M) {
  const Eigen::Vector2d u = b - a, v = c - a, w = c - b;
  const double area = 0.5 * (u.x() * v.y() - u.y() * v.x());
  const double edges = u.dot(M * u) + v.dot(M * v) + w.dot(M * w);
  return edges > 0.0 ? 4.0 * std::sqrt(3.0) * area * std::sqrt(M.determinant()) / edges : 0.0;
}

int smooth_free_nodes(Eigen::Matrix2Xd& x, const Eigen::MatrixXi& tri,
                      const std::vector<char>& free_node, const MetricField& metric, int sweeps) {
  const Eigen::Index n = x.cols();
  // The triangles round each node, as the other two corners counter-clockwise.
  std::vector<std::vector<std::array<int, 2>>> star(static_cast<std::size_t>(n));
  for (Eigen::Index t = 0; t < tri.cols(); ++t)
    for (int k = 0; k < 3; ++k)
      star[tri(k, t)].push_back({tri((k + 1) % 3, t), tri((k + 2) % 3, t)});
  // Worst and summed quality of v's triangles with v at p.
  const auto patch = [&](const std::vector<std::array<int, 2>>& s, const Eigen::Vector2d& p,
                         const Eigen::Matrix2d& M) {
    double worst = std::numeric_limits<double>::infinity(), sum = 0.0;
    for (const auto& [a, b] : s) {
      const double q = metric_mean_ratio(p, x.col(a), x.col(b), M);
      worst = std::min(worst, q);
      sum += q;
    }
    return std::pair<double, double>{worst, sum};
  };
  int moves = 0;
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (Eigen::Index v = 0; v < n; ++v) {
      const auto& s = star[v];
      if (!free_node[v] || s.empty()) continue;
      const Eigen::Vector2d p = x.col(v);
      const Eigen::Matrix2d M = metric.metric_at(p);
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(M);
      const Eigen::Matrix2d root = eig.operatorSqrt(), root_inv = eig.operatorInverseSqrt();
      Eigen::Matrix2d R;
      R << 0, -1, 1, 0;
      const Eigen::Matrix2d turn = 0.5 * std::sqrt(3.0) * root_inv * R * root;
      Eigen::Vector2d laplace = Eigen::Vector2d::Zero(), apex = Eigen::Vector2d::Zero();
      for (const auto& [a, b] : s) {
        // Each neighbour appears in two triangles of an interior star.
        laplace += 0.5 * (x.col(a) + x.col(b));
        apex += 0.5 * (x.col(a) + x.col(b)) + turn * (x.col(b) - x.col(a));
      }
      laplace /= static_cast<double>(s.size());
      apex /= static_cast<double>(s.size());
      auto best = patch(s, p, M);
      Eigen::Vector2d to = p;
      for (const Eigen::Vector2d& c : {laplace, apex}) {
        const auto q = patch(s, c, M);
        if (q.first >= best.first && q.second > best.second + 1e-12) {
          best = q;
          to = c;
        }
      }
      // Where the worst triangle stays poor, compass search on it: the 8
      // steps of length h round the best point so far, h halved on failure.
      if (best.first < kPoor) {
        double h = 0.25 * std::sqrt((x.col(s.front()[0]) - p).squaredNorm());
        for (int k = 0; k < kSearchSteps; ++k) {
          bool better = false;
          for (int d = 0; d < 8; ++d) {
            const Eigen::Vector2d c =
                to + h * Eigen::Vector2d(std::cos(M_PI * d / 4), std::sin(M_PI * d / 4));
            const auto q = patch(s, c, M);
            if (q.first > best.first + 1e-12) {
              best = q;
              to = c;
              better = true;
            }
          }
          if (!better) h *= 0.5;
        }
      }
      if (to != p) {
        x.col(v) = to;
        ++moves;
      }
    }
  return moves;
}

}  // namespace homesh
