#include "voronoi/seeding/curve_division.h"

#include <algorithm>
#include <cmath>

namespace homesh {

std::vector<double> divide_by_metric_length(const Eigen::VectorXd& u, const Eigen::Matrix2Xd& x,
                                            const MetricField& metric, int min_pieces) {
  const Eigen::Index n = x.cols() - 1;
  std::vector<double> s(n + 1, 0.0);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Vector2d v = x.col(k + 1) - x.col(k);
    s[k + 1] = s[k] + std::sqrt(v.dot(metric.metric_at(0.5 * (x.col(k) + x.col(k + 1))) * v));
  }
  const int m = std::max(min_pieces, static_cast<int>(std::lround(s[n])));
  std::vector<double> out{u(0)};
  Eigen::Index k = 0;
  for (int j = 1; j < m; ++j) {
    const double want = s[n] * j / m;
    while (k + 1 < n && s[k + 1] < want) ++k;
    const double t = s[k + 1] > s[k] ? (want - s[k]) / (s[k + 1] - s[k]) : 0.0;
    out.push_back(u(k) + t * (u(k + 1) - u(k)));
  }
  out.push_back(u(n));
  return out;
}

}  // namespace homesh
