#pragma once
// A conforming triangulation of a polygonal domain from a crystal dual: the
// dual's triangles where they are right, a constrained Delaunay triangulation
// (CGAL) of the same seeds where they are not.
//
// The crystal dual can miss the boundary: a boundary seed's region may be cut
// off from the next boundary seed's by an interior region reaching the
// boundary (no dual edge along the boundary), a dual triangle may reach
// outside a concave boundary, and faults the refinement could not repair
// leave gaps or overlaps. A dual triangle is kept if it turns
// counter-clockwise, its centroid is inside the polygon, it crosses no
// boundary segment and no kept triangle's edge, no boundary segment runs the
// wrong way along it, and no other kept triangle shares a directed edge with
// it. The kept triangles' edges and the boundary segments then constrain a
// constrained Delaunay triangulation of all the seeds: it holds every kept
// triangle that no seed lies inside, and fills the rest of the polygon.
#include <Eigen/Core>
#include <array>
#include <vector>

namespace homesh {

struct ConformingTriangulation {
  /// Counter-clockwise seed triples, each rotated to start at its smallest
  /// index, sorted: a triangulation of the polygon whose edges include every
  /// boundary segment.
  std::vector<std::array<int, 3>> triangles;
  int from_dual = 0;     ///< triangles that are dual triangles
  int filled = 0;        ///< triangles the constrained Delaunay added
  int dual_dropped = 0;  ///< dual triangles not used
  /// Boundary segments no dual triangle had (the dual missed the boundary).
  int boundary_missed = 0;
};

/// seeds: 2 by S; boundary: the polygon's segments as seed pairs (a, b), the
/// domain on the left of a -> b, forming closed loops; dual: seed triples.
/// Throws homesh::Error if the boundary segments cross.
ConformingTriangulation conforming_triangulation(const Eigen::Matrix2Xd& seeds,
                                                 const std::vector<std::array<int, 2>>& boundary,
                                                 const std::vector<std::array<int, 3>>& dual);

}  // namespace homesh
