#include "voronoi/seeding/boundary_encroachment.h"

#include <algorithm>

namespace homesh {

std::vector<int> encroaching_seeds(const Eigen::Matrix2Xd& seeds, int fixed,
                                   const std::vector<std::array<int, 2>>& segments) {
  std::vector<char> inside(seeds.cols(), 0);
  for (const auto& [a, b] : segments) {
    const Eigen::Vector2d c = 0.5 * (seeds.col(a) + seeds.col(b));
    const double r2 = 0.25 * (seeds.col(a) - seeds.col(b)).squaredNorm();
    for (int s = fixed; s < seeds.cols(); ++s)
      if ((seeds.col(s) - c).squaredNorm() < r2) inside[s] = 1;
  }
  std::vector<int> out;
  for (int s = fixed; s < seeds.cols(); ++s)
    if (inside[s]) out.push_back(s);
  return out;
}

}  // namespace homesh
