#include "layers/wall_loops.h"

#include <algorithm>
#include <utility>

#include "core/error.h"
#include "core/node_triangles.h"
#include "layers/plane_geometry.h"

namespace homesh {
namespace {

using layers_detail::point_text;

std::string node_text(const Mesh& m, int node) {
  return "node " + std::to_string(node + 1) + " at " + point_text(m.x.col(node));
}

}  // namespace

std::vector<WallLoop> wall_loops(const Mesh& m, const std::vector<int>& curves) {
  // The triangles listing the edge a b (either way), with their direction (from
  // the smaller node to the larger), found round a (core/node_triangles.h): a
  // map of every edge cost 5 % of the layers stage.
  const NodeTriangles round(m);
  std::vector<std::pair<int, bool>> sides_of;
  auto triangles_of = [&](int a, int b) -> const std::vector<std::pair<int, bool>>& {
    sides_of.clear();
    for (const int* t = round.begin(a); t != round.end(a); ++t)
      for (int i = 0; i < 3; ++i) {
        const int p = m.tri(i, *t), q = m.tri((i + 1) % 3, *t);
        if ((p == a && q == b) || (p == b && q == a)) sides_of.push_back({*t, p < q});
      }
    return sides_of;
  };

  const int n = m.num_nodes();
  std::vector<int> next(n, -1), left(n, -1), curve(n, -1), incoming(n, 0);
  // Non-wall boundary lines, directed with the domain on the left: index by end node.
  std::vector<std::vector<int>> side_from(n), side_to(n);
  std::vector<int> side_tail(m.num_lines(), -1), side_head(m.num_lines(), -1),
      side_left(m.num_lines(), -1);
  int count = 0;
  for (int k = 0; k < m.num_lines(); ++k) {
    const bool wall = std::binary_search(curves.begin(), curves.end(), m.line_entity[k]);
    const int a = m.line(0, k), b = m.line(1, k);
    const std::vector<std::pair<int, bool>>& found = triangles_of(a, b);
    const std::size_t sides = found.size();
    if (!wall) {
      if (sides != 1) continue;
      const auto [e, forward] = found.front();
      side_tail[k] = forward == (a < b) ? a : b;
      side_head[k] = side_tail[k] == a ? b : a;
      side_left[k] = e;
      side_from[side_tail[k]].push_back(k);
      side_to[side_head[k]].push_back(k);
      continue;
    }
    ++count;
    if (sides != 1)
      throw Error("layers: the wall line from " + node_text(m, a) + " to " + node_text(m, b) +
                  " on curve " + std::to_string(m.line_entity[k]) + " bounds " +
                  std::to_string(sides) + " triangles; a wall must bound the domain (one)");
    const auto [e, forward] = found.front();
    // The triangle is counter-clockwise: its own edge direction has it on the left.
    const int from = forward == (a < b) ? a : b, to = from == a ? b : a;
    if (next[from] >= 0 || incoming[to] > 0)
      throw Error("layers: wall " + node_text(m, next[from] >= 0 ? from : to) +
                  " joins more than two wall lines");
    next[from] = to;
    left[from] = e;
    curve[from] = m.line_entity[k];
    ++incoming[to];
  }
  if (count == 0) throw Error("layers: the walls have no boundary lines in the mesh");

  // The one non-wall boundary line at an open end.
  auto end_line = [&](int v, const std::vector<int>& lines) {
    if (lines.size() != 1)
      throw Error("layers: the open wall ends at " + node_text(m, v) + ", on " +
                  std::to_string(lines.size()) +
                  " other boundary lines; an open wall must end on exactly one (or close)");
    return lines.front();
  };

  std::vector<WallLoop> loops;
  std::vector<bool> done(n, false);
  std::vector<bool> used(m.num_lines(), false);
  for (const bool open : {true, false})
    for (int start = 0; start < n; ++start) {
      if (next[start] < 0 || done[start] || (open && incoming[start] > 0)) continue;
      WallLoop loop;
      loop.closed = !open;
      int v = start;
      while (v >= 0 && !done[v]) {
        done[v] = true;
        loop.nodes.push_back(v);
        loop.triangles.push_back(left[v]);
        loop.curves.push_back(curve[v]);
        if (open && next[v] < 0) {
          const int k = end_line(v, side_from[v]);
          loop.ends[1] = side_head[k];
          loop.end_lines[1] = k;
          loop.triangles.back() = side_left[k];
          loop.curves.back() = m.line_entity[k];
        }
        v = next[v];
      }
      if (open) {
        const int k = end_line(start, side_to[start]);
        loop.ends[0] = side_tail[k];
        loop.end_lines[0] = k;
        for (const int line : loop.end_lines) {
          if (used[line])
            throw Error("layers: the boundary line from " + node_text(m, m.line(0, line)) + " to " +
                        node_text(m, m.line(1, line)) +
                        " ends two open walls; mesh it with more than one line");
          used[line] = true;
        }
      }
      loops.push_back(std::move(loop));
    }
  return loops;
}

}  // namespace homesh
