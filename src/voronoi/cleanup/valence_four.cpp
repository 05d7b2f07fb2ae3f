#include "voronoi/cleanup/valence_four.h"

#include <algorithm>
#include <array>

#include "core/node_triangles.h"

namespace homesh {
namespace {

constexpr int kMaxRounds = 10;

}  // namespace

std::vector<int> remove_valence_four(Mesh& m, const std::vector<char>& free_node,
                                     const TriangleQuality& quality, double gain) {
  std::vector<int> removed;
  const auto corners = [&m](int a, int b, int c) {
    Eigen::Matrix<double, 2, 3> X;
    X << m.x.col(a), m.x.col(b), m.x.col(c);
    return X;
  };
  const auto q = [&](int a, int b, int c) { return quality(corners(a, b, c)); };
  const auto ccw = [&](int a, int b, int c) {
    const Eigen::Vector2d u = m.x.col(b) - m.x.col(a), v = m.x.col(c) - m.x.col(a);
    return u.x() * v.y() - u.y() * v.x() > 0.0;
  };
  for (int round = 0; round < kMaxRounds; ++round) {
    const NodeTriangles around(m);
    std::vector<char> gone(m.tri.cols(), 0);
    std::vector<std::array<int, 3>> added;
    std::vector<int> added_entity;
    const std::size_t before = removed.size();
    for (int v = 0; v < m.num_nodes(); ++v) {
      if (!free_node[v] || around.end(v) - around.begin(v) != 4) continue;
      const std::vector<int> s(around.begin(v), around.end(v));
      if (std::any_of(s.begin(), s.end(), [&](int t) { return gone[t] != 0; }) ||
          std::any_of(s.begin(), s.end(),
                      [&](int t) { return m.tri_entity[t] != m.tri_entity[s[0]]; }))
        continue;
      // Each triangle (v, a, b) counter-clockwise from v; the ring links b of
      // one to a of the next.
      std::array<std::array<int, 2>, 4> ab;
      for (int k = 0; k < 4; ++k) {
        int i = 0;
        while (m.tri(i, s[k]) != v) ++i;
        ab[k] = {m.tri((i + 1) % 3, s[k]), m.tri((i + 2) % 3, s[k])};
      }
      std::array<int, 4> ring{ab[0][0], ab[0][1], -1, -1};
      bool closed = true;
      for (int k = 2; k < 4 && closed; ++k) {
        const auto next = std::find_if(
            ab.begin(), ab.end(), [&](const std::array<int, 2>& e) { return e[0] == ring[k - 1]; });
        closed = next != ab.end();
        if (closed) ring[k] = (*next)[1];
      }
      if (!closed || std::none_of(ab.begin(), ab.end(), [&](const std::array<int, 2>& e) {
            return e[0] == ring[3] && e[1] == ring[0];
          }))
        continue;
      double worst = 1e300;
      for (const auto& [a, b] : ab) worst = std::min(worst, q(v, a, b));
      double best = -1e300;
      int split = -1;
      for (int d = 0; d < 2; ++d) {
        const int a = ring[d], b = ring[d + 1], c = ring[d + 2], e = ring[(d + 3) % 4];
        if (!ccw(a, b, c) || !ccw(a, c, e)) continue;
        const double w = std::min(q(a, b, c), q(a, c, e));
        if (w > best) {
          best = w;
          split = d;
        }
      }
      if (split < 0 || best <= worst + gain) continue;
      for (const int t : s) gone[t] = 1;
      const int a = ring[split], b = ring[split + 1], c = ring[split + 2],
                e = ring[(split + 3) % 4];
      added.push_back({a, b, c});
      added.push_back({a, c, e});
      added_entity.insert(added_entity.end(), 2, m.tri_entity[s[0]]);
      removed.push_back(v);
    }
    if (removed.size() == before) break;
    const Eigen::Index kept = std::count(gone.begin(), gone.end(), 0);
    Eigen::MatrixXi tri(3, kept + static_cast<Eigen::Index>(added.size()));
    std::vector<int> entity;
    Eigen::Index col = 0;
    for (Eigen::Index t = 0; t < m.tri.cols(); ++t)
      if (!gone[t]) {
        tri.col(col++) = m.tri.col(t);
        entity.push_back(m.tri_entity[t]);
      }
    for (std::size_t k = 0; k < added.size(); ++k) {
      tri.col(col++) << added[k][0], added[k][1], added[k][2];
      entity.push_back(added_entity[k]);
    }
    m.tri = std::move(tri);
    m.tri_entity = std::move(entity);
  }
  std::sort(removed.begin(), removed.end());
  return removed;
}

}  // namespace homesh
