#include "voronoi/engines/morton_order.h"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace homesh {

std::vector<int> morton_order(const CartesianGrid& g, const Eigen::Matrix2Xd& points) {
  // Bit b of v to bit 2 b.
  const auto spread_bits = [](std::uint64_t v) {
    std::uint64_t out = 0;
    for (int b = 0; b < 32; ++b) out |= ((v >> b) & 1u) << (2 * b);
    return out;
  };
  const int P = static_cast<int>(points.cols());
  std::vector<std::pair<std::uint64_t, int>> key(P);
  for (int p = 0; p < P; ++p) {
    const Eigen::Vector2d rel = points.col(p) - g.origin;
    const auto i = static_cast<std::uint64_t>(std::max(0.0, rel.x() / g.dx));
    const auto j = static_cast<std::uint64_t>(std::max(0.0, rel.y() / g.dy));
    key[p] = {spread_bits(i) | (spread_bits(j) << 1), p};
  }
  std::sort(key.begin(), key.end());
  std::vector<int> order(P);
  for (int p = 0; p < P; ++p) order[p] = key[p].second;
  return order;
}

}  // namespace homesh
