#include "voronoi/cleanup/metric_smoothing.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace homesh {
namespace {

constexpr double kPoor = 0.8;              // below this worst quality, the compass search too
constexpr int kSearchSteps = 24;           // compass search: at most this many steps
constexpr double kSearchTolerance = 1e-3;  // and until the step is this fraction of the first

// The triangles round each node, as the other two corners counter-clockwise.
using Star = std::vector<std::array<int, 2>>;
std::vector<Star> stars(Eigen::Index n, const Eigen::MatrixXi& tri) {
  std::vector<Star> star(static_cast<std::size_t>(n));
  for (Eigen::Index t = 0; t < tri.cols(); ++t)
    for (int k = 0; k < 3; ++k)
      star[tri(k, t)].push_back({tri((k + 1) % 3, t), tri((k + 2) % 3, t)});
  return star;
}

// The same metric for every triangle of a star: its determinant's root
// taken once, and each triangle's edge opposite the node, w^T M w, which no
// position of the node changes (metric_mean_ratio's value, to the last bit: the
// same products in the same order).
struct StarMetric {
  Eigen::Matrix2d M;
  double root_det;
  std::vector<double> opposite;  // per triangle of the star
  StarMetric(const Eigen::Matrix2d& m, const Eigen::Matrix2Xd& x, const Star& s)
      : M(m), root_det(std::sqrt(m.determinant())) {
    opposite.reserve(s.size());
    for (const auto& [a, b] : s) {
      const Eigen::Vector2d w = x.col(b) - x.col(a);
      opposite.push_back(w.dot(M * w));
    }
  }
  // Triangle k of the star with the node at a.
  double mean_ratio(std::size_t k, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                    const Eigen::Vector2d& c) const {
    const Eigen::Vector2d u = b - a, v = c - a;
    const double area = 0.5 * (u.x() * v.y() - u.y() * v.x());
    const double edges = u.dot(M * u) + v.dot(M * v) + opposite[k];
    return edges > 0.0 ? 4.0 * std::sqrt(3.0) * area * root_det / edges : 0.0;
  }
};

// Worst quality of a node's triangles with the node at p, and the sum of
// their inverse qualities (infinite once one folds or degenerates).
struct Patch {
  double worst, inverse;
};
Patch patch(const Eigen::Matrix2Xd& x, const Star& s, const Eigen::Vector2d& p,
            const StarMetric& M) {
  Patch out{std::numeric_limits<double>::infinity(), 0.0};
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double q = M.mean_ratio(k, p, x.col(s[k][0]), x.col(s[k][1]));
    out.worst = std::min(out.worst, q);
    out.inverse += q > 0.0 ? 1.0 / q : std::numeric_limits<double>::infinity();
  }
  return out;
}

// Compass search from `to`: the 8 steps of length h round the best point so
// far, h halved on failure, until h is kSearchTolerance of the first or
// kSearchSteps halvings.
template <class Better>
void compass(const Eigen::Matrix2Xd& x, const Star& s, const StarMetric& M, double h,
             Eigen::Vector2d& to, Patch& best, Better better) {
  static const std::array<Eigen::Vector2d, 8> direction = [] {
    std::array<Eigen::Vector2d, 8> out;
    for (int d = 0; d < 8; ++d) out[d] = {std::cos(M_PI * d / 4), std::sin(M_PI * d / 4)};
    return out;
  }();
  const double stop = h * kSearchTolerance;
  for (int k = 0; k < kSearchSteps && h > stop; ++k) {
    bool moved = false;
    for (int d = 0; d < 8; ++d) {
      const Eigen::Vector2d c = to + h * direction[d];
      const Patch q = patch(x, s, c, M);
      if (better(q, best)) {
        best = q;
        to = c;
        moved = true;
      }
    }
    if (!moved) h *= 0.5;
  }
}

bool raises_worst(const Patch& q, const Patch& b) { return q.worst > b.worst + 1e-12; }

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
  const std::vector<Star> star = stars(n, tri);
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
      const StarMetric star_metric(M, x, s);
      Patch best = patch(x, s, p, star_metric);
      // No worse worst triangle, and a smaller sum of inverse qualities.
      const auto smaller_sum = [](double floor) {
        return [floor](const Patch& q, const Patch& b) {
          return q.worst >= floor && q.inverse < b.inverse * (1 - 1e-12);
        };
      };
      Eigen::Vector2d to = p;
      for (const Eigen::Vector2d& c : {laplace, apex}) {
        const Patch q = patch(x, s, c, star_metric);
        if (smaller_sum(best.worst)(q, best)) {
          best = q;
          to = c;
        }
      }
      const double h = 0.25 * std::sqrt((x.col(s.front()[0]) - p).squaredNorm());
      // Where the worst triangle stays poor, raise it first.
      if (best.worst < kPoor) compass(x, s, star_metric, h, to, best, raises_worst);
      // Then the sum of inverse qualities (Knupp's inverse mean ratio), the
      // worst triangle kept no worse: the star's optimum, where the fixed
      // candidates above only come near it.
      compass(x, s, star_metric, h, to, best, smaller_sum(best.worst));
      if (to != p) {
        x.col(v) = to;
        ++moves;
      }
    }
  return moves;
}

int raise_worst_triangle(Eigen::Matrix2Xd& x, const Eigen::MatrixXi& tri,
                         const std::vector<char>& free_node, const MetricField& metric,
                         int max_steps) {
  const std::vector<Star> star = stars(x.cols(), tri);
  const auto quality = [&](Eigen::Index t) {
    const Eigen::Vector2d a = x.col(tri(0, t)), b = x.col(tri(1, t)), c = x.col(tri(2, t));
    return metric_mean_ratio(a, b, c, metric.metric_at((a + b + c) / 3));
  };
  // Each triangle's quality, kept up to date as its corners move.
  std::vector<std::vector<Eigen::Index>> node_triangles(static_cast<std::size_t>(x.cols()));
  std::vector<double> q(static_cast<std::size_t>(tri.cols()));
  for (Eigen::Index t = 0; t < tri.cols(); ++t) {
    q[t] = quality(t);
    for (int k = 0; k < 3; ++k) node_triangles[tri(k, t)].push_back(t);
  }
  int steps = 0;
  for (; steps < max_steps; ++steps) {
    Eigen::Index worst = 0;
    double q_worst = std::numeric_limits<double>::infinity();
    for (Eigen::Index t = 0; t < tri.cols(); ++t)
      if (q[t] < q_worst) {
        q_worst = q[t];
        worst = t;
      }
    bool moved = false;
    for (int k = 0; k < 3; ++k) {
      const int v = tri(k, worst);
      if (!free_node[v]) continue;
      const Eigen::Vector2d p = x.col(v);
      const StarMetric M(metric.metric_at(p), x, star[v]);
      Patch best = patch(x, star[v], p, M);
      Eigen::Vector2d to = p;
      compass(x, star[v], M, 0.25 * (x.col(star[v].front()[0]) - p).norm(), to, best, raises_worst);
      if (to != p) {
        x.col(v) = to;
        for (const Eigen::Index t : node_triangles[v]) q[t] = quality(t);
        moved = true;
      }
    }
    if (!moved) break;
  }
  return steps;
}

}  // namespace homesh
