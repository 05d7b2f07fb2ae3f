#include "layers/wall_loops.h"

#include <algorithm>
#include <map>
#include <utility>

#include "core/error.h"
#include "layers/plane_geometry.h"

namespace homesh {
namespace {

using layers_detail::point_text;

std::string node_text(const Mesh& m, int node) {
  return "node " + std::to_string(node + 1) + " at " + point_text(m.x.col(node));
}

}  // namespace

std::vector<int> wall_curves(const Mesh& m, const std::vector<std::string>& walls) {
  if (walls.empty()) throw Error("layers: no walls given (walls=NAME,... of curve groups or tags)");
  std::vector<int> curves;
  for (const std::string& w : walls) {
    bool found = false;
    for (const PhysicalGroup& g : m.physicals)
      if (g.dim == 1 && g.name == w) {
        curves.insert(curves.end(), g.entities.begin(), g.entities.end());
        found = true;
      }
    if (!found && !w.empty() && w.find_first_not_of("0123456789") == std::string::npos) {
      const int tag = std::stoi(w);
      found = std::any_of(m.entities.begin(), m.entities.end(),
                          [&](const Entity& e) { return e.dim == 1 && e.tag == tag; }) ||
              std::find(m.line_entity.begin(), m.line_entity.end(), tag) != m.line_entity.end();
      if (found) curves.push_back(tag);
    }
    if (!found) {
      std::string known;
      for (const PhysicalGroup& g : m.physicals)
        if (g.dim == 1 && !g.name.empty()) known += (known.empty() ? "" : ", ") + g.name;
      throw Error("layers: no wall '" + w + "': not a curve physical group (" +
                  (known.empty() ? "none" : known) + ") nor a curve tag of the mesh");
    }
  }
  std::sort(curves.begin(), curves.end());
  curves.erase(std::unique(curves.begin(), curves.end()), curves.end());
  return curves;
}

std::vector<WallLoop> wall_loops(const Mesh& m, const std::vector<int>& curves) {
  // Each undirected triangle edge -> the triangles listing it, with their direction.
  std::map<std::pair<int, int>, std::vector<std::pair<int, bool>>> edges;
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int i = 0; i < 3; ++i) {
      const int a = m.tri(i, e), b = m.tri((i + 1) % 3, e);
      edges[{std::min(a, b), std::max(a, b)}].push_back({e, a < b});
    }

  const int n = m.num_nodes();
  std::vector<int> next(n, -1), left(n, -1), curve(n, -1), incoming(n, 0);
  int count = 0;
  for (int k = 0; k < m.num_lines(); ++k) {
    if (!std::binary_search(curves.begin(), curves.end(), m.line_entity[k])) continue;
    ++count;
    const int a = m.line(0, k), b = m.line(1, k);
    const auto it = edges.find({std::min(a, b), std::max(a, b)});
    const std::size_t sides = it == edges.end() ? 0 : it->second.size();
    if (sides != 1)
      throw Error("layers: the wall line from " + node_text(m, a) + " to " + node_text(m, b) +
                  " on curve " + std::to_string(m.line_entity[k]) + " bounds " +
                  std::to_string(sides) + " triangles; a wall must bound the domain (one)");
    const auto [e, forward] = it->second.front();
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

  std::vector<WallLoop> loops;
  std::vector<bool> done(n, false);
  for (int start = 0; start < n; ++start) {
    if (next[start] < 0 || done[start]) continue;
    WallLoop loop;
    int v = start;
    while (!done[v]) {
      if (next[v] < 0)
        throw Error("layers: the wall ends at " + node_text(m, v) +
                    "; walls must form closed loops (choose all curves around the wall)");
      done[v] = true;
      loop.nodes.push_back(v);
      loop.triangles.push_back(left[v]);
      loop.curves.push_back(curve[v]);
      v = next[v];
    }
    if (v != start)
      throw Error("layers: the wall from " + node_text(m, start) + " joins a loop at " +
                  node_text(m, v) + " without closing; walls must form closed loops");
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace homesh
