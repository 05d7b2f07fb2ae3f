#include "voronoi/dual/region_analysis.h"

#include <algorithm>
#include <limits>
#include <set>

namespace homesh {
namespace {

// Connected components of the nodes where `member` holds, 4- or 8-neighbour
// adjacency: component id per node (-1 for non-members) and the count.
template <class Member, class Joined>
int components(const CartesianGrid& g, Member&& member, Joined&& joined, bool eight,
               std::vector<int>& id) {
  id.assign(g.node_count(), -1);
  int count = 0;
  std::vector<int> stack;
  for (int start = 0; start < g.node_count(); ++start) {
    if (id[start] >= 0 || !member(start)) continue;
    id[start] = count;
    stack.push_back(start);
    while (!stack.empty()) {
      const int n = stack.back();
      stack.pop_back();
      const int i = n % g.nx, j = n / g.nx;
      for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
          if ((di == 0 && dj == 0) || (!eight && di != 0 && dj != 0)) continue;
          const int a = i + di, b = j + dj;
          if (a < 0 || b < 0 || a >= g.nx || b >= g.ny) continue;
          const int m = g.index(a, b);
          if (id[m] >= 0 || !member(m) || !joined(n, m)) continue;
          id[m] = count;
          stack.push_back(m);
        }
      }
    }
    ++count;
  }
  return count;
}

}  // namespace

RegionReport analyse_regions(const CartesianGrid& g, const Eigen::VectorXi& labels,
                             const Eigen::Matrix2Xd& seeds, const Eigen::VectorXd& domain) {
  const auto inside = [&](int n) { return domain.size() == 0 || domain(n) <= 0.0; };
  const auto on_boundary = [&](int i, int j) {
    if (i == 0 || j == 0 || i == g.nx - 1 || j == g.ny - 1) return true;
    return !inside(g.index(i - 1, j)) || !inside(g.index(i + 1, j)) || !inside(g.index(i, j - 1)) ||
           !inside(g.index(i, j + 1));
  };

  RegionReport out;
  std::vector<int> id;
  const auto any = [](int, int) { return true; };
  const int count = components(
      g, [&](int n) { return inside(n) && labels(n) >= 0; },
      [&](int n, int m) { return labels(n) == labels(m); }, true, id);
  out.regions.resize(count);
  std::vector<int> first_node(count, -1);
  std::vector<std::set<int>> neighbours(count);
  std::set<std::array<int, 2>> adjacent, boundary_pairs;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const int n = g.index(i, j);
      if (!inside(n)) continue;
      if (labels(n) < 0) {
        ++out.unreached;
        continue;
      }
      Region& r = out.regions[id[n]];
      if (r.nodes == 0) first_node[id[n]] = n;
      r.label = labels(n);
      ++r.nodes;
      const bool edge_node = on_boundary(i, j);
      r.touches_boundary = r.touches_boundary || edge_node;
      for (const auto& [a, b] : {std::array<int, 2>{i + 1, j}, std::array<int, 2>{i, j + 1}}) {
        if (a >= g.nx || b >= g.ny) continue;
        const int m = g.index(a, b);
        if (!inside(m) || labels(m) < 0 || labels(m) == labels(n)) continue;
        neighbours[id[n]].insert(labels(m));
        neighbours[id[m]].insert(labels(n));
        const std::array<int, 2> pair{std::min(labels(n), labels(m)),
                                      std::max(labels(n), labels(m))};
        adjacent.insert(pair);
        if (edge_node || on_boundary(a, b)) boundary_pairs.insert(pair);
      }
    }
  }
  for (int c = 0; c < count; ++c)
    out.regions[c].neighbours.assign(neighbours[c].begin(), neighbours[c].end());
  out.adjacent.assign(adjacent.begin(), adjacent.end());
  out.boundary_pairs.assign(boundary_pairs.begin(), boundary_pairs.end());

  // A seed's region holds the node labelled with it nearest to the seed,
  // within kSeedReach cells (a seed on the boundary may have its nearest
  // node outside).
  constexpr int kSeedReach = 2;
  std::vector<int> region_of_seed(seeds.cols(), -1);
  for (int s = 0; s < seeds.cols(); ++s) {
    const Eigen::Vector2i p = g.nearest_node(seeds.col(s));
    double best = std::numeric_limits<double>::infinity();
    for (int j = std::max(p.y() - kSeedReach, 0); j <= std::min(p.y() + kSeedReach, g.ny - 1); ++j)
      for (int i = std::max(p.x() - kSeedReach, 0); i <= std::min(p.x() + kSeedReach, g.nx - 1);
           ++i) {
        const int n = g.index(i, j);
        const double d = (g.point(i, j) - seeds.col(s)).squaredNorm();
        if (inside(n) && labels(n) == s && d < best) {
          best = d;
          region_of_seed[s] = id[n];
        }
      }
    if (region_of_seed[s] >= 0)
      out.regions[region_of_seed[s]].seeded = true;
    else
      out.missing.push_back(s);
  }
  // The connected parts of the domain (4-neighbour), and the seeded regions
  // in each.
  std::vector<int> part;
  const int parts = components(g, inside, any, false, part);
  std::vector<int> seeded_in_part(parts, 0);
  for (int c = 0; c < count; ++c) {
    if (out.regions[c].seeded)
      ++seeded_in_part[part[first_node[c]]];
    else
      out.orphans.push_back(c);
  }
  for (int s = 0; s < seeds.cols(); ++s) {
    const int c = region_of_seed[s];
    if (c >= 0 && out.regions[c].neighbours.size() == 1 && seeded_in_part[part[first_node[c]]] >= 3)
      out.isolated.push_back(s);
  }

  if (domain.size() > 0) {
    std::vector<int> outside_id;
    const int outside_parts = components(
        g, [&](int n) { return !inside(n); }, any, true, outside_id);
    std::vector<int> open(outside_parts, 0);
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        if ((i == 0 || j == 0 || i == g.nx - 1 || j == g.ny - 1) && outside_id[g.index(i, j)] >= 0)
          open[outside_id[g.index(i, j)]] = 1;
    out.domain_euler = parts - static_cast<int>(std::count(open.begin(), open.end(), 0));
  }
  return out;
}

}  // namespace homesh
