#pragma once
// The sweep behind every edge flip of homesh (flip_edges in edge_flips.h, the
// valence flips of voronoi/cleanup/valence_flips.h): each edge shared by two
// counter-clockwise triangles of one surface, not a line element, is offered
// to a choice; a chosen edge flips to the quad's other diagonal. A template,
// not a std::function: the layers stage flips after every load step.
#include <algorithm>
#include <cstdint>
#include <iterator>
#include <vector>

#include "core/mesh.h"

namespace homesh {

/// 0, 1, ..., m.num_triangles() - 1: every triangle, for flip_edges_where.
inline std::vector<int> all_triangles(const Mesh& m) {
  std::vector<int> all(m.num_triangles());
  for (int e = 0; e < m.num_triangles(); ++e) all[e] = e;
  return all;
}

/// Sweeps the edges shared by two of `triangles` (distinct indices of m's
/// triangles), triangles (a, b, c) and (b, a, d) of the same surface, the
/// edge (a, b) no line element: where choose(a, b, c, d) returns true they
/// become (c, d, b) and (d, c, a). A triangle flipped in a sweep is not
/// offered again in it; sweeps until none flips, at most max_sweeps. Returns
/// the flips.
template <class Choose>
int flip_edges_where(Mesh& m, const std::vector<int>& triangles, Choose&& choose, int max_sweeps) {
  // Edges as 64-bit keys (a << 32 | b). Sorted vectors, not maps: open_room calls
  // this after every load step on the whole mesh, and a std::map of its 3 N
  // directed edges cost 75 % of the layers stage at 1.1 M triangles.
  const auto key = [](int a, int b) { return (std::int64_t(a) << 32) | std::uint32_t(b); };
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
      if (!choose(a, b, c, d)) continue;
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
