#include "voronoi/seeding/boundary_encroachment.h"

#include <algorithm>

#include "voronoi/metric/metric_field.h"

namespace homesh {

std::vector<int> encroaching_seeds(const Eigen::Matrix2Xd& seeds, int fixed,
                                   const std::vector<std::array<int, 2>>& segments,
                                   const MetricField* metric) {
  std::vector<char> inside(seeds.cols(), 0);
  for (const auto& [a, b] : segments) {
    const Eigen::Vector2d c = 0.5 * (seeds.col(a) + seeds.col(b));
    // x in the diametral circle of (a, b) in M: (x - a)^T M (x - b) < 0, the
    // angle at x obtuse in M (for M = I: |x - c| < |a - b| / 2).
    const Eigen::Matrix2d M = metric ? metric->metric_at(c) : Eigen::Matrix2d::Identity();
    for (int s = fixed; s < seeds.cols(); ++s)
      if ((seeds.col(s) - seeds.col(a)).dot(M * (seeds.col(s) - seeds.col(b))) < 0) inside[s] = 1;
  }
  std::vector<int> out;
  for (int s = fixed; s < seeds.cols(); ++s)
    if (inside[s]) out.push_back(s);
  return out;
}

}  // namespace homesh
