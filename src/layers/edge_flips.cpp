#include "layers/edge_flips.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <utility>
#include <vector>

#include "layers/plane_geometry.h"
#include "layers/radius_ratio.h"

namespace homesh {
namespace {

std::vector<int> all_triangles(const Mesh& m) {
  std::vector<int> all(m.num_triangles());
  for (int e = 0; e < m.num_triangles(); ++e) all[e] = e;
  return all;
}

double plain_radius_ratio(const Eigen::Matrix<double, 2, 3>& X) { return radius_ratio(X); }

// The flips with q(X) of counter-clockwise triangles X (a template: open_room
// flips after every load step, no call through a std::function per triangle
// for the radius ratio).
template <class Q>
int flip_edges_by(Mesh& m, const std::vector<int>& triangles, const Q& q, double gain,
                  int max_sweeps) {
  const auto quality = [&](const Mesh& mesh, int a, int b, int c) {
    Eigen::Matrix<double, 2, 3> X;
    X << mesh.x.col(a), mesh.x.col(b), mesh.x.col(c);
    return layers_detail::orient(X.col(0), X.col(1), X.col(2)) > 0 ? q(X) : -1.0;
  };
  // Edges as 64-bit keys (a << 32 | b). Sorted vectors, not maps: open_room calls
  // this after every load step on the whole mesh, and a std::map of its 3 N
  // directed edges cost 75 % of the layers stage at 1.1 M triangles.
  auto key = [](int a, int b) { return (std::int64_t(a) << 32) | std::uint32_t(b); };
  std::vector<std::int64_t> lines;
  for (int k = 0; k < m.num_lines(); ++k) {
    const auto [a, b] = std::minmax(m.line(0, k), m.line(1, k));
    lines.push_back(key(a, b));
  }
  std::sort(lines.begin(), lines.end());
  struct Side {
    std::int64_t edge;  ///< directed edge (a, b) listed counter-clockwise by triangle e
    int e, c;           ///< the triangle and its third node
  };
  std::vector<Side> side(3 * triangles.size());
  const auto by_edge = [](const Side& s, const Side& t) { return s.edge < t.edge; };
  int flips = 0;
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    for (std::size_t t = 0; t < triangles.size(); ++t)
      for (int i = 0, e = triangles[t]; i < 3; ++i)
        side[3 * t + i] = {key(m.tri(i, e), m.tri((i + 1) % 3, e)), e, m.tri((i + 2) % 3, e)};
    // Stable: of repeated directed edges (a non-conforming mesh) the last listed wins.
    std::stable_sort(side.begin(), side.end(), by_edge);
    std::vector<bool> touched(m.num_triangles(), false);
    int flipped = 0;
    for (std::size_t k = 0; k < side.size(); ++k) {
      if (k + 1 < side.size() && side[k + 1].edge == side[k].edge) continue;
      const int a = int(side[k].edge >> 32), b = int(std::uint32_t(side[k].edge));
      if (a > b) continue;
      const Side twin{key(b, a), 0, 0};
      const auto it = std::upper_bound(side.begin(), side.end(), twin, by_edge);
      if (it == side.begin() || std::prev(it)->edge != twin.edge) continue;
      const int e = side[k].e, c = side[k].c, f = std::prev(it)->e, d = std::prev(it)->c;
      if (touched[e] || touched[f] || m.tri_entity[e] != m.tri_entity[f] ||
          std::binary_search(lines.begin(), lines.end(), side[k].edge))
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

}  // namespace

int flip_edges(Mesh& m, double gain, int max_sweeps) {
  return flip_edges_by(m, all_triangles(m), plain_radius_ratio, gain, max_sweeps);
}

int flip_edges(Mesh& m, const std::vector<int>& triangles, double gain, int max_sweeps) {
  return flip_edges_by(m, triangles, plain_radius_ratio, gain, max_sweeps);
}

int flip_edges(Mesh& m, const TriangleQuality& quality, double gain, int max_sweeps) {
  return flip_edges_by(m, all_triangles(m), quality, gain, max_sweeps);
}

}  // namespace homesh
