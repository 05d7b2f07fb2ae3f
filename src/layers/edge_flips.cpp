#include "layers/edge_flips.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "layers/plane_geometry.h"
#include "layers/radius_ratio.h"

namespace homesh {
namespace {

double quality(const Mesh& m, int a, int b, int c) {
  Eigen::Matrix<double, 2, 3> X;
  X << m.x.col(a), m.x.col(b), m.x.col(c);
  return layers_detail::orient(X.col(0), X.col(1), X.col(2)) > 0 ? radius_ratio(X) : -1.0;
}

}  // namespace

int flip_edges(Mesh& m, double gain, int max_sweeps) {
  std::set<std::pair<int, int>> lines;
  for (int k = 0; k < m.num_lines(); ++k)
    lines.insert(std::minmax(m.line(0, k), m.line(1, k)));
  int flips = 0;
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    // Directed edge (a, b) -> triangle listing it counter-clockwise, and its third node.
    std::map<std::pair<int, int>, std::pair<int, int>> side;
    for (int e = 0; e < m.num_triangles(); ++e)
      for (int i = 0; i < 3; ++i)
        side[{m.tri(i, e), m.tri((i + 1) % 3, e)}] = {e, m.tri((i + 2) % 3, e)};
    std::vector<bool> touched(m.num_triangles(), false);
    int flipped = 0;
    for (const auto& [edge, left] : side) {
      const auto [a, b] = edge;
      if (a > b) continue;
      const auto it = side.find({b, a});
      if (it == side.end()) continue;
      const auto [e, c] = left;
      const auto [f, d] = it->second;
      if (touched[e] || touched[f] || m.tri_entity[e] != m.tri_entity[f] || lines.count(edge))
        continue;
      // Triangles (a, b, c) and (b, a, d); the other diagonal gives (c, d, b) and (d, c, a).
      const double now = std::min(quality(m, a, b, c), quality(m, b, a, d));
      const double then = std::min(quality(m, c, d, b), quality(m, d, c, a));
      if (!(then > now + gain)) continue;
      m.tri.col(e) << c, d, b;
      m.tri.col(f) << d, c, a;
      touched[e] = touched[f] = true;
      ++flipped;
    }
    flips += flipped;
    if (flipped == 0) break;
  }
  return flips;
}

}  // namespace homesh
