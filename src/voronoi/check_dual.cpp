#include "voronoi/check_dual.h"

#include <map>
#include <set>

#include "voronoi/orient2d.h"

namespace homesh {

DualCheck check_dual(const Eigen::Matrix2Xd& seeds, const DualTriangulation& dual,
                     const RegionReport& regions) {
  DualCheck out;
  out.vertices = static_cast<int>(seeds.cols() - regions.missing.size());
  out.edges = static_cast<int>(dual.edges.size());
  out.triangles = static_cast<int>(dual.triangles.size());
  out.euler = out.vertices - out.edges + out.triangles;
  out.expected_euler = regions.domain_euler;

  std::map<std::array<int, 2>, int> uses;
  for (const auto& e : dual.edges) uses[e] = 0;
  for (const auto& t : dual.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
    if (orient2d(seeds.col(t[0]), seeds.col(t[1]), seeds.col(t[2])) <= 0) ++out.inverted;
  }
  const std::set<std::array<int, 2>> boundary(regions.boundary_pairs.begin(),
                                              regions.boundary_pairs.end());
  for (const auto& [e, n] : uses) {
    if (boundary.count(e))
      out.bad_boundary_edges += n > 1;
    else
      out.bad_interior_edges += n != 2;
  }
  return out;
}

}  // namespace homesh
