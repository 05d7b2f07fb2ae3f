#include "optim/rank_correlation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "core/error.h"

namespace homesh {

Eigen::VectorXd ranks(const Eigen::VectorXd& v, double relative_tie) {
  const auto n = v.size();
  std::vector<Eigen::Index> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](Eigen::Index a, Eigen::Index b) { return v[a] < v[b]; });
  const double tie = n > 0 ? relative_tie * v.cwiseAbs().maxCoeff() : 0.0;
  Eigen::VectorXd r(n);
  for (Eigen::Index start = 0; start < n;) {
    Eigen::Index end = start + 1;
    while (end < n && v[order[end]] - v[order[end - 1]] <= tie) ++end;
    const double mean_rank = 0.5 * static_cast<double>(start + end - 1) + 1.0;
    for (Eigen::Index k = start; k < end; ++k) r[order[k]] = mean_rank;
    start = end;
  }
  return r;
}

double spearman(const Eigen::VectorXd& a, const Eigen::VectorXd& b, double relative_tie) {
  if (a.size() != b.size() || a.size() < 2) {
    throw Error("rank correlation needs two samples of the same size >= 2");
  }
  const Eigen::VectorXd ra = ranks(a, relative_tie), rb = ranks(b, relative_tie);
  const Eigen::VectorXd da = ra.array() - ra.mean(), db = rb.array() - rb.mean();
  const double norm = da.norm() * db.norm();
  if (!(norm > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return da.dot(db) / norm;
}

}  // namespace homesh
