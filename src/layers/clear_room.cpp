#include "layers/clear_room.h"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <utility>

#include "core/node_triangles.h"
#include "core/progress.h"
#include "layers/plane_geometry.h"
#include "layers/radius_ratio.h"

namespace homesh {
namespace {

using layers_detail::orient;

bool in_triangle(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                 const Eigen::Vector2d& c) {
  const double s = orient(a, b, c);
  if (s == 0) return false;
  const double sign = s > 0 ? 1 : -1;
  return sign * orient(a, b, p) >= 0 && sign * orient(b, c, p) >= 0 && sign * orient(c, a, p) >= 0;
}

int corner(const Mesh& m, int e, int v) {
  for (int i = 0; i < 3; ++i)
    if (m.tri(i, e) == v) return i;
  return -1;
}

}  // namespace

std::vector<int> clear_room(Mesh& m, const Room& room, const std::vector<bool>& free, double margin,
                            double min_quality) {
  const int lines = static_cast<int>(room.front.size());
  std::vector<int> prev(lines, -1), line_of(m.num_nodes(), -1);
  for (int k = 0; k < lines; ++k) {
    if (room.next[k] >= 0) prev[room.next[k]] = k;
    line_of[room.front[k]] = k;
  }
  auto far = [&](int k) -> Eigen::Vector2d {
    const Eigen::Vector2d w = m.x.col(room.wall[k]);
    return w + margin * (room.target.col(k) - w);
  };
  // In the room of the lines within 3 of line k (the quads a -> next(a)).
  auto in_room = [&](const Eigen::Vector2d& p, int k) {
    int a = k;
    for (int s = 0; s < 3 && prev[a] >= 0 && prev[a] != k; ++s) a = prev[a];
    for (int s = 0; s < 7 && room.next[a] >= 0; ++s, a = room.next[a]) {
      const int b = room.next[a];
      const Eigen::Vector2d wa = m.x.col(room.wall[a]), wb = m.x.col(room.wall[b]);
      if (in_triangle(p, wa, wb, far(b)) || in_triangle(p, wa, far(b), far(a))) return true;
    }
    return false;
  };

  // Node -> triangles (core/node_triangles.h), each node's list copied out when
  // it is first asked for, as only the nodes near the front are: open_room calls
  // this after every step on the whole mesh.
  const NodeTriangles incident(m);
  std::unordered_map<int, std::vector<int>> lists;
  auto around = [&](int v) -> std::vector<int>& {
    auto it = lists.find(v);
    if (it == lists.end())
      it = lists.emplace(v, std::vector<int>(incident.begin(v), incident.end(v))).first;
    return it->second;  // stays valid: unordered_map keeps its elements in place
  };
  std::vector<bool> dead(m.num_triangles(), false), removed(m.num_nodes(), false);
  std::vector<int> gone, mark(m.num_nodes(), -1);
  int stamp = 0;

  // The free nodes in the room, reached from the front through free nodes in
  // the room, each tested against the lines near the front node it came from.
  std::vector<int> near(m.num_nodes(), -1), queue;
  for (int k = 0; k < lines; ++k) {
    near[room.front[k]] = k;
    queue.push_back(room.front[k]);
  }
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const int u = queue[q];
    for (int e : around(u))
      for (int i = 0; i < 3; ++i) {
        const int v = m.tri(i, e);
        if (near[v] >= 0 || !free[v] || line_of[v] >= 0 || !in_room(m.x.col(v), near[u])) continue;
        near[v] = near[u];
        queue.push_back(v);
      }
  }
  auto inside = [&](int v) { return near[v] >= 0 && line_of[v] < 0 && !removed[v]; };

  // Scratch lists of collapse, kept across calls (no allocation per attempt).
  std::vector<int> shared, apexes, moved, outside;
  auto collapse = [&](int v, int f) {
    // The triangles of edge f v and the apexes they share; v's other triangles.
    shared.clear();
    apexes.clear();
    moved.clear();
    for (int e : around(v)) {
      if (corner(m, e, f) >= 0) {
        shared.push_back(e);
        for (int i = 0; i < 3; ++i)
          if (m.tri(i, e) != v && m.tri(i, e) != f) apexes.push_back(m.tri(i, e));
      } else {
        moved.push_back(e);
      }
    }
    if (shared.empty()) return false;
    // Manifold: the only common neighbours of f and v are the apexes.
    ++stamp;
    for (int e : around(f))
      for (int i = 0; i < 3; ++i) mark[m.tri(i, e)] = stamp;
    for (int e : moved)
      for (int i = 0; i < 3; ++i) {
        const int a = m.tri(i, e);
        if (a != v && mark[a] == stamp &&
            std::find(apexes.begin(), apexes.end(), a) == apexes.end())
          return false;
      }
    for (int e : moved) {
      Eigen::Matrix<double, 2, 3> p;
      int on_front[3], fronts = 0;
      for (int i = 0; i < 3; ++i) {
        const int a = m.tri(i, e), b = a == v ? f : a;
        p.col(i) = m.x.col(b);
        if (line_of[b] >= 0) on_front[fronts++] = line_of[b];
      }
      // No triangle across the room: front nodes only of consecutive lines, two at most.
      if (fronts == 3) return false;
      if (fronts == 2 && room.next[on_front[0]] != on_front[1] &&
          room.next[on_front[1]] != on_front[0])
        return false;
      if (!(orient(p.col(0), p.col(1), p.col(2)) > 0) || radius_ratio(p) < min_quality)
        return false;
    }
    for (int e : shared) {
      dead[e] = true;
      for (int i = 0; i < 3; ++i) {
        std::vector<int>& list = around(m.tri(i, e));
        list.erase(std::find(list.begin(), list.end(), e));
      }
    }
    for (int e : moved) {
      m.tri(corner(m, e, v), e) = f;
      around(f).push_back(e);
    }
    around(v).clear();
    removed[v] = true;
    gone.push_back(v);
    return true;
  };

  Progress progress("clearing room", 0);
  for (bool changed = true; changed;) {
    changed = false;
    progress.update(0, std::to_string(gone.size()) + " nodes removed");
    std::vector<std::pair<double, std::pair<int, int>>> candidates;  // (distance, (v, f))
    for (int k = 0; k < lines; ++k) {
      const int f = room.front[k];
      for (int e : around(f))
        for (int i = 0; i < 3; ++i) {
          const int v = m.tri(i, e);
          if (inside(v))
            candidates.push_back({(m.x.col(v) - m.x.col(room.wall[k])).norm(), {v, f}});
        }
    }
    std::sort(candidates.begin(), candidates.end());
    for (const auto& c : candidates) {
      const int v = c.second.first, f = c.second.second;
      if (removed[v]) continue;
      bool done = collapse(v, f);
      // Else onto another neighbour, those beyond the room first.
      outside.clear();
      for (int e : around(v))
        for (int i = 0; i < 3 && !done; ++i) {
          const int w = m.tri(i, e);
          if (w != v && line_of[w] < 0) outside.push_back(w);
        }
      std::stable_partition(outside.begin(), outside.end(), [&](int w) { return !inside(w); });
      for (std::size_t j = 0; j < outside.size() && !done; ++j) done = collapse(v, outside[j]);
      changed = changed || done;
    }
  }

  int kept = 0;
  for (int e = 0; e < m.num_triangles(); ++e)
    if (!dead[e]) {
      m.tri.col(kept) = m.tri.col(e);
      m.tri_entity[kept] = m.tri_entity[e];
      ++kept;
    }
  m.tri.conservativeResize(3, kept);
  m.tri_entity.resize(kept);
  return gone;
}

std::vector<int> drop_unused_nodes(Mesh& m) {
  const int count = m.num_nodes();
  std::vector<bool> used(count, false);
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int i = 0; i < m.tri.rows(); ++i) used[m.tri(i, e)] = true;
  for (int e = 0; e < m.num_quads(); ++e)
    for (int i = 0; i < m.quad.rows(); ++i) used[m.quad(i, e)] = true;
  for (int l = 0; l < m.num_lines(); ++l)
    for (int i = 0; i < m.line.rows(); ++i) used[m.line(i, l)] = true;
  for (int v : m.point_node) used[v] = true;
  std::vector<int> map(count);
  for (int i = 0; i < count; ++i) map[i] = used[i] ? i : -1;
  int last = count - 1, hole = 0;
  while (true) {
    while (last >= 0 && !used[last]) --last;
    while (hole < last && used[hole]) ++hole;
    if (hole >= last) break;
    m.x.col(hole) = m.x.col(last);
    m.node_class[hole] = m.node_class[last];
    map[last] = hole;
    used[hole] = true;
    used[last] = false;
  }
  const int size = last + 1;
  m.x.conservativeResize(2, size);
  m.node_class.resize(size);
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int i = 0; i < m.tri.rows(); ++i) m.tri(i, e) = map[m.tri(i, e)];
  for (int e = 0; e < m.num_quads(); ++e)
    for (int i = 0; i < m.quad.rows(); ++i) m.quad(i, e) = map[m.quad(i, e)];
  for (int l = 0; l < m.num_lines(); ++l)
    for (int i = 0; i < m.line.rows(); ++i) m.line(i, l) = map[m.line(i, l)];
  for (int& v : m.point_node) v = map[v];
  return map;
}

}  // namespace homesh
