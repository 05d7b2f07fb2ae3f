#pragma once
// Adapter to CGAL 5.5's constrained Delaunay triangulation (header-only, built
// with CGAL_DISABLE_GMP as in cgal_delaunay.h).
#include <Eigen/Core>
#include <array>
#include <vector>

namespace homesh {

/// The constrained Delaunay triangulation (exact predicates) of points (2 by
/// n) with the segments `boundary` and `constraints` (column-index pairs that
/// may touch only at their ends), restricted to the faces reached from the
/// unbounded face across an odd number of `boundary` segments. Returns
/// counter-clockwise column-index triples, each rotated to start at its
/// smallest index, sorted. Throws homesh::Error if segments cross (CGAL would
/// have to add their intersection as a point) or a segment runs through a
/// point.
std::vector<std::array<int, 3>> cgal_constrained_triangles(
    const Eigen::Matrix2Xd& points, const std::vector<std::array<int, 2>>& boundary,
    const std::vector<std::array<int, 2>>& constraints);

}  // namespace homesh
