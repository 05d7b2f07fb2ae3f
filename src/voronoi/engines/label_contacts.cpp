#include "voronoi/engines/label_contacts.h"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace homesh {

LabelContacts label_contacts(const StencilField& field, const Eigen::VectorXi& labels, int count) {
  const CartesianGrid& g = field.grid();
  // Pairs as a * 2^32 + b: one integer compare to sort them.
  std::vector<std::uint64_t> pairs;
  std::vector<char> contact(count, 0);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const int a = labels(g.index(i, j));
      if (a < 0) continue;
      for (const auto& [di, dj] : {std::pair<int, int>{1, 0}, {0, 1}, {-1, 0}, {0, -1}}) {
        const int ii = i + di, jj = j + dj;
        if (ii < 0 || jj < 0 || ii >= g.nx || jj >= g.ny) continue;
        const int n = g.index(ii, jj);
        if (!field.inside(n)) {
          contact[a] = 1;
          continue;
        }
        const int b = labels(n);
        const std::uint64_t pair = (static_cast<std::uint64_t>(a) << 32) | b;
        if (b > a && (pairs.empty() || pairs.back() != pair)) pairs.push_back(pair);
      }
    }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  LabelContacts out;
  for (const std::uint64_t pair : pairs)
    out.collisions.push_back({static_cast<int>(pair >> 32), static_cast<int>(pair & 0xffffffffu)});
  for (int s = 0; s < count; ++s)
    if (contact[s] && field.has_domain()) out.boundary_contacts.push_back(s);
  return out;
}

}  // namespace homesh
