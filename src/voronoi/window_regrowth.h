#pragma once
// A finer grid where the global one is too coarse for the seeds. Where the
// crystal dual misses boundary segments (seeds a cell or two apart, as at a
// sharp trailing edge), the crystals round the spot grow again on a grid over
// a window about it, `cells` cells per local seed spacing, and the window's
// dual triangles replace the global ones there.
//
// The seam: the metric Voronoi diagram is local, so a Voronoi vertex inside
// the window's inner box, with the window's seeds reaching `margin` beyond
// it, is found by both grids, each to its own accuracy. The window supplies
// the dual triangles whose Voronoi vertex (DualTriangulation::vertices) lies
// in the inner box, the global dual the others; conforming_triangulation
// then checks their union (and fills what still disagrees at the seam).
#include <Eigen/Core>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "voronoi/voronoi_problem.h"

namespace homesh {

struct WindowOptions {
  double cells = 6.0;  ///< window grid cells per shortest missed segment
  int max_nodes = 1200;  ///< window grid nodes along the longer side, at most
  /// Inner box: the missed segments' box grown by this many times the
  /// metric's largest size there (1 / sqrt(lambda_min)); the window's seeds
  /// and grid reach as far again beyond it.
  double pad = 2.0;
};

/// Boundary segments (seed pairs) that are an edge of no triangle.
std::vector<std::array<int, 2>> missed_segments(const std::vector<std::array<int, 2>>& segments,
                                                const std::vector<std::array<int, 3>>& triangles);

struct RegrownDual {
  Eigen::Matrix2Xd seeds;                     ///< the input seeds, then those the windows added
  std::vector<std::array<int, 3>> triangles;  ///< the merged dual
  int windows = 0;                            ///< windows grown
  int window_nodes = 0;                       ///< grid nodes of the largest window (per side)
};

/// problem: the global problem (its metric field; seed_metrics are not
/// used), its seeds those of `triangles` (2 by S) and
/// its dual `triangles` with their Voronoi vertices `vertices` (2 by T).
/// segments: the boundary seed pairs; domain_on: the domain's level set on
/// any grid (as VoronoiProblem::domain). The missed segments are clustered
/// (those within 2 pads of each other share a window), each cluster's window
/// regrown by refine_dual with `engine`, and the duals merged as above.
/// Windows no finer than the global grid are not grown.
RegrownDual regrow_windows(const VoronoiProblem& problem,
                           const std::vector<std::array<int, 3>>& triangles,
                           const Eigen::Matrix2Xd& vertices,
                           const std::vector<std::array<int, 2>>& segments,
                           const std::function<Eigen::VectorXd(const CartesianGrid&)>& domain_on,
                           const std::string& engine, const WindowOptions& options = {});

}  // namespace homesh
