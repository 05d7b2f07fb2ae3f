#include "voronoi/cleanup/valence_three.h"

#include <algorithm>

namespace homesh {

int remove_valence_three(std::vector<std::array<int, 3>>& triangles,
                         std::vector<int>& triangle_surface, const std::vector<char>& interior) {
  int removed = 0;
  for (;;) {
    // The triangles round each interior node (up to 4 kept: only 3 matter).
    std::vector<std::vector<int>> star(interior.size());
    for (std::size_t f = 0; f < triangles.size(); ++f)
      for (const int v : triangles[f])
        if (interior[v] && star[v].size() < 4) star[v].push_back(static_cast<int>(f));
    std::vector<char> gone(triangles.size(), 0);
    std::vector<std::array<int, 3>> added;
    std::vector<int> added_surface;
    int round = 0;
    for (std::size_t v = 0; v < star.size(); ++v) {
      const std::vector<int>& s = star[v];
      if (s.size() != 3 || gone[s[0]] || gone[s[1]] || gone[s[2]]) continue;
      if (triangle_surface[s[0]] != triangle_surface[s[1]] ||
          triangle_surface[s[0]] != triangle_surface[s[2]])
        continue;
      // Each triangle (v, a, b) counter-clockwise from v: a closed fan links
      // b of one to a of the next, and the union is (a0, b0, b1).
      std::array<std::array<int, 2>, 3> ab;
      for (int k = 0; k < 3; ++k) {
        const std::array<int, 3>& t = triangles[s[k]];
        const int i =
            static_cast<int>(std::find(t.begin(), t.end(), static_cast<int>(v)) - t.begin());
        ab[k] = {t[(i + 1) % 3], t[(i + 2) % 3]};
      }
      const int next = ab[1][0] == ab[0][1] ? 1 : 2, last = 3 - next;
      if (ab[next][0] != ab[0][1] || ab[last][0] != ab[next][1] || ab[0][0] != ab[last][1])
        continue;
      for (const int f : s) gone[f] = 1;
      added.push_back({ab[0][0], ab[0][1], ab[next][1]});
      added_surface.push_back(triangle_surface[s[0]]);
      ++round;
    }
    if (round == 0) return removed;
    removed += round;
    std::vector<std::array<int, 3>> kept;
    std::vector<int> kept_surface;
    for (std::size_t f = 0; f < triangles.size(); ++f)
      if (!gone[f]) {
        kept.push_back(triangles[f]);
        kept_surface.push_back(triangle_surface[f]);
      }
    kept.insert(kept.end(), added.begin(), added.end());
    kept_surface.insert(kept_surface.end(), added_surface.begin(), added_surface.end());
    triangles = std::move(kept);
    triangle_surface = std::move(kept_surface);
  }
}

}  // namespace homesh
