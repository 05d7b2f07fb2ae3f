#pragma once
// Validity checks of a dual triangulation (dual_triangulation.h) against the
// regions it came from (region_analysis.h).
#include <Eigen/Core>
#include <array>
#include <vector>

#include "voronoi/dual/dual_triangulation.h"
#include "voronoi/dual/region_analysis.h"

namespace homesh {

struct DualCheck {
  int vertices = 0;  ///< seeds with a region
  int edges = 0;
  int triangles = 0;
  int euler = 0;           ///< vertices - edges + triangles
  int expected_euler = 1;  ///< Euler characteristic of the domain
  /// Interior edges (interface not reaching the boundary) in other than two
  /// triangles.
  int bad_interior_edges = 0;
  /// Boundary edges (interface reaching the boundary) in more than one triangle.
  int bad_boundary_edges = 0;
  /// Triangles whose seeds do not turn counter-clockwise in the order of their
  /// regions round the Voronoi vertex (exact orient2d <= 0).
  int inverted = 0;
  /// Indices into dual.triangles of the triangles at fault: inverted, or
  /// holding a bad interior or boundary edge; sorted.
  std::vector<int> bad_triangles;
  /// Interior edges in no triangle: nothing marks where they fail.
  std::vector<std::array<int, 2>> lone_edges;

  bool ok() const {
    return euler == expected_euler && bad_interior_edges == 0 && bad_boundary_edges == 0 &&
           inverted == 0;
  }
};

/// seeds: 2 by S. The Euler characteristic V - E + F of the dual of a
/// partition of the domain into simply connected regions equals the domain's.
DualCheck check_dual(const Eigen::Matrix2Xd& seeds, const DualTriangulation& dual,
                     const RegionReport& regions);

}  // namespace homesh
