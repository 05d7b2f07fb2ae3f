#pragma once
// The Delaunay triangulation dual to a crystal partition (thesis Section 2.7:
// "joining two seeds with a line segment if a collision between them was
// detected").
//
// Edges: the colliding pairs, and the pairs of regions adjacent along a grid
// edge of the label image that never collided (a Voronoi edge shorter than a
// cell can be a gap between frozen fronts, filled afterwards).
//
// Triangles: the Voronoi vertices, read off the label image. A grid cell whose
// 4 corners carry 3 distinct labels holds the triple point of those 3
// regions; the labels met going counter-clockwise round the cell give the
// triangle's vertex order, so an inverted dual triangle shows up as a
// clockwise seed triple (see check_dual.h). A cell with 4 distinct labels
// a, b, c, d (counter-clockwise) holds a near-degenerate vertex, split along
// the diagonal whose seeds collided, or, if both or neither did, by the
// in-circle test in the local metric: with M = L L^T at the cell centre and
// points mapped by x -> L^T x, the diagonal b-d is taken if d lies inside the
// circle through a, b, c, else a-c. A triple becomes a triangle only if its
// three seeds are pairwise joined.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "voronoi/grid/cartesian_grid.h"
#include "voronoi/metric/metric_field.h"

namespace homesh {

struct DualTriangulation {
  /// Seed pairs {a, b}, a < b, sorted: the collisions and label-adjacent
  /// pairs, with the 4-label resolution's added_edges and without its
  /// dropped_edges.
  std::vector<std::array<int, 2>> edges;
  int adjacency_edges = 0;  ///< pairs adjacent in the labels that never collided
  /// Seed triples in the counter-clockwise order of their regions round the
  /// Voronoi vertex, sorted.
  std::vector<std::array<int, 3>> triangles;
  /// The Voronoi vertex of each triangle: the mean centre of the grid cells
  /// that showed its triple (2 by #triangles).
  Eigen::Matrix2Xd vertices;
  /// Where the label image shows a triple point that gives no triangle
  /// (unjoined seeds) or gives one in both orders (orientation conflict): the
  /// mean centre of its cells (2 by #defects).
  Eigen::Matrix2Xd defects;
  int triple_cells = 0;  ///< cells with 3 distinct labels
  int quad_cells = 0;    ///< cells with 4 distinct labels
  /// Cells with labels a, b, a, c round them (two corners of one region
  /// facing across the cell): the triple is oriented by its seeds instead.
  int ambiguous_cells = 0;
  /// Triples seen at a triple point whose seeds are not pairwise joined.
  int unjoined_triples = 0;
  /// Triples met in both cyclic orders (majority kept).
  int orientation_conflicts = 0;
  std::vector<std::array<int, 2>> added_edges;    ///< diagonals chosen that never collided
  std::vector<std::array<int, 2>> dropped_edges;  ///< collided diagonals not chosen
};

/// labels: grid.node_count() crystal ids (-1: none); seeds: 2 by S;
/// collisions: colliding pairs {a, b}, a < b; adjacent: label pairs {a, b},
/// a < b, adjacent along a grid edge (RegionReport::adjacent); metric: for the
/// in-circle test.
DualTriangulation dual_triangulation(const CartesianGrid& grid, const Eigen::VectorXi& labels,
                                     const Eigen::Matrix2Xd& seeds,
                                     const std::vector<std::array<int, 2>>& collisions,
                                     const std::vector<std::array<int, 2>>& adjacent,
                                     const MetricField& metric);

}  // namespace homesh
