#include "voronoi/cleanup/valence_flips.h"

#include <algorithm>
#include <cstdint>

#include "core/error.h"

namespace homesh {
namespace {

std::int64_t key(int a, int b) { return (std::int64_t(a) << 32) | std::uint32_t(b); }

double orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

}  // namespace

int flip_to_regular_valence(Mesh& m, const std::vector<char>& interior,
                            const TriangleQuality& quality, double floor, int max_sweeps) {
  if (m.order != 1) throw Error("flip_to_regular_valence: the mesh must be linear");
  if (interior.size() != static_cast<std::size_t>(m.num_nodes()))
    throw Error("flip_to_regular_valence: one interior flag per node is needed");
  std::vector<int> valence(m.num_nodes(), 0);
  for (Eigen::Index t = 0; t < m.tri.cols(); ++t)
    for (int k = 0; k < 3; ++k) ++valence[m.tri(k, t)];
  const auto energy = [&](int v, int change) {
    if (!interior[v]) return 0;
    const int d = valence[v] + change - 6;
    return d * d;
  };
  const auto q = [&](int a, int b, int c) {
    Eigen::Matrix<double, 2, 3> X;
    X << m.x.col(a), m.x.col(b), m.x.col(c);
    return orientation(X.col(0), X.col(1), X.col(2)) > 0 ? quality(X) : -1.0;
  };
  std::vector<std::int64_t> lines;
  for (int k = 0; k < m.num_lines(); ++k) {
    const auto [a, b] = std::minmax(m.line(0, k), m.line(1, k));
    lines.push_back(key(a, b));
  }
  std::sort(lines.begin(), lines.end());
  struct Side {
    std::int64_t edge;  // directed (a, b), counter-clockwise in triangle e
    int e, c;           // the triangle and its third node
  };
  const auto by_edge = [](const Side& s, const Side& t) { return s.edge < t.edge; };
  std::vector<Side> side(3 * m.tri.cols());
  int flips = 0;
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    for (Eigen::Index e = 0; e < m.tri.cols(); ++e)
      for (int i = 0; i < 3; ++i)
        side[3 * e + i] = {key(m.tri(i, e), m.tri((i + 1) % 3, e)), static_cast<int>(e),
                           m.tri((i + 2) % 3, e)};
    std::sort(side.begin(), side.end(), by_edge);
    std::vector<char> touched(m.tri.cols(), 0);
    int flipped = 0;
    for (const Side& s : side) {
      const int a = int(s.edge >> 32), b = int(std::uint32_t(s.edge));
      if (a > b) continue;
      const auto it = std::lower_bound(side.begin(), side.end(), Side{key(b, a), 0, 0}, by_edge);
      if (it == side.end() || it->edge != key(b, a)) continue;
      const int e = s.e, c = s.c, f = it->e, d = it->c;
      if (touched[e] || touched[f] || m.tri_entity[e] != m.tri_entity[f] ||
          std::binary_search(lines.begin(), lines.end(), key(std::min(a, b), std::max(a, b))))
        continue;
      const int before = energy(a, 0) + energy(b, 0) + energy(c, 0) + energy(d, 0);
      const int after = energy(a, -1) + energy(b, -1) + energy(c, 1) + energy(d, 1);
      if (after >= before) continue;
      // Triangles (a, b, c) and (b, a, d); the other diagonal gives (c, d, b) and (d, c, a).
      const double now = std::min(q(a, b, c), q(b, a, d));
      if (std::min(q(c, d, b), q(d, c, a)) < std::min(floor, now)) continue;
      m.tri.col(e) << c, d, b;
      m.tri.col(f) << d, c, a;
      --valence[a], --valence[b], ++valence[c], ++valence[d];
      touched[e] = touched[f] = 1;
      ++flipped;
    }
    flips += flipped;
    if (flipped == 0) break;
  }
  return flips;
}

}  // namespace homesh
