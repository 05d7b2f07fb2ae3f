#include "voronoi/dual/check_dual.h"

#include <algorithm>
#include <map>
#include <set>

#include "voronoi/grid/orient2d.h"

namespace homesh {

DualCheck check_dual(const Eigen::Matrix2Xd& seeds, const DualTriangulation& dual,
                     const RegionReport& regions) {
  DualCheck out;
  out.vertices = static_cast<int>(seeds.cols() - regions.missing.size());
  out.edges = static_cast<int>(dual.edges.size());
  out.triangles = static_cast<int>(dual.triangles.size());
  out.euler = out.vertices - out.edges + out.triangles;
  out.expected_euler = regions.domain_euler;

  const auto edge = [](int a, int b) { return std::array<int, 2>{std::min(a, b), std::max(a, b)}; };
  std::map<std::array<int, 2>, int> uses;
  for (const auto& e : dual.edges) uses[e] = 0;
  std::set<int> bad;
  for (int f = 0; f < static_cast<int>(dual.triangles.size()); ++f) {
    const auto& t = dual.triangles[f];
    for (int k = 0; k < 3; ++k) ++uses[edge(t[k], t[(k + 1) % 3])];
    if (orient2d(seeds.col(t[0]), seeds.col(t[1]), seeds.col(t[2])) <= 0) {
      ++out.inverted;
      bad.insert(f);
    }
  }
  const std::set<std::array<int, 2>> boundary(regions.boundary_pairs.begin(),
                                              regions.boundary_pairs.end());
  std::set<std::array<int, 2>> bad_edges;
  for (const auto& [e, n] : uses) {
    const bool on_boundary = boundary.count(e) > 0;
    if (on_boundary ? n > 1 : n != 2) {
      (on_boundary ? out.bad_boundary_edges : out.bad_interior_edges) += 1;
      bad_edges.insert(e);
      if (n == 0) out.lone_edges.push_back(e);
    }
  }
  for (int f = 0; f < static_cast<int>(dual.triangles.size()); ++f) {
    const auto& t = dual.triangles[f];
    for (int k = 0; k < 3; ++k)
      if (bad_edges.count(edge(t[k], t[(k + 1) % 3]))) bad.insert(f);
  }
  out.bad_triangles.assign(bad.begin(), bad.end());
  return out;
}

}  // namespace homesh
