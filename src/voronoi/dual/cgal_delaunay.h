#pragma once
// Adapter to CGAL 5.5 (header-only; its .cpp is built with CGAL::CGAL's usage
// requirements and CGAL_DISABLE_GMP, see CMakeLists.txt, so that no GMP library
// is linked: exact fall-backs use CGAL's own number types). Every translation
// unit of a program that includes CGAL must agree on that macro.
#include <Eigen/Core>
#include <array>
#include <vector>

namespace homesh {

/// The Delaunay triangulation of points (2 by n) by CGAL, with exact
/// predicates: triangles as counter-clockwise column-index triples, each
/// rotated to start at its smallest index, sorted.
std::vector<std::array<int, 3>> cgal_delaunay_triangles(const Eigen::Matrix2Xd& points);

/// The Voronoi cells of points (2 by n) under the Euclidean distance, from
/// CGAL's Delaunay triangulation: for each point its cell's vertices (the
/// circumcentres of its Delaunay triangles, counter-clockwise) and its
/// Delaunay neighbours (in the same turn). A point on the convex hull has an
/// unbounded cell: no vertices. Duplicate points: the later copies get
/// neither.
struct VoronoiCells {
  std::vector<std::vector<Eigen::Vector2d>> vertices;
  std::vector<std::vector<int>> neighbours;
};
VoronoiCells cgal_voronoi_cells(const Eigen::Matrix2Xd& points);

/// CGAL::orientation of a, b, c: +1 counter-clockwise, -1 clockwise, 0 collinear.
int cgal_orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

}  // namespace homesh
