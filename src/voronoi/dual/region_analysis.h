#pragma once
// The Voronoi regions of a label image (one crystal id per grid node) and the
// defects that forbid a valid dual Delaunay triangulation (thesis Section 2.1
// footnotes, Section 2.7): orphan regions, with no seed, and isolated
// regions, interior to another region.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "voronoi/grid/cartesian_grid.h"

namespace homesh {

/// A connected set of grid nodes with the same label, 8-neighbour adjacency
/// (a crystal grows diagonally by one cell in a step, and gaps filled between
/// frozen fronts can leave it joined at a corner only).
struct Region {
  int label = -1;
  int nodes = 0;
  bool seeded = false;  ///< holds the node with its label nearest its seed (within 2 cells)
  bool touches_boundary = false;  ///< has a node on the grid border or next to the outside
  std::vector<int> neighbours;    ///< labels of the regions sharing a grid edge, sorted
};

struct RegionReport {
  std::vector<Region> regions;
  /// Indices into regions of the regions holding no seed (orphans).
  std::vector<int> orphans;
  /// Seeds whose region has exactly one neighbouring region while its part of
  /// the domain holds at least three regions: interior to another region, or
  /// engulfed against the boundary (Fig 2.3a). Such a seed is a vertex of no
  /// dual triangle.
  std::vector<int> isolated;
  /// Seeds with no region at all (their crystal was swallowed).
  std::vector<int> missing;
  /// Domain nodes with no label (reached by no crystal).
  int unreached = 0;
  /// Label pairs {a, b}, a < b, adjacent along a grid edge, sorted.
  std::vector<std::array<int, 2>> adjacent;
  /// The adjacent pairs whose interface reaches the domain (or grid) boundary:
  /// their dual edge is on the boundary of the dual triangulation.
  std::vector<std::array<int, 2>> boundary_pairs;
  /// Euler characteristic of the domain: components minus holes.
  int domain_euler = 1;
};

/// labels: grid.node_count() crystal ids (-1: none); seeds: 2 by S; domain:
/// empty (the whole grid) or the level set of VoronoiProblem::domain (< 0
/// inside).
RegionReport analyse_regions(const CartesianGrid& grid, const Eigen::VectorXi& labels,
                             const Eigen::Matrix2Xd& seeds, const Eigen::VectorXd& domain);

}  // namespace homesh
