#pragma once
// A finer grid where the global one is too coarse for the seeds. Where the
// crystal dual misses boundary segments (seeds a cell or two apart, as at a
// sharp trailing edge), the crystals round the spot grow again on a grid over
// a window about it, `cells` cells per local seed spacing and at least
// `finer` times finer than the global grid, and the window's dual triangles
// replace the global ones there. A window that still misses some of its
// segments grows again twice as fine, up to `max_nodes` per side: a triple
// point of two boundary crystals and an interior one a fraction of a global
// cell inside the wall (NACA-7526, docs/voronoi.md) needs a few window cells
// between it and the wall.
//
// The seam: the metric Voronoi diagram is local, so a Voronoi vertex inside
// the window's inner box, with the window's seeds reaching `margin` beyond
// it, is found by both grids, each to its own accuracy. The window supplies
// the dual triangles whose Voronoi vertex (DualTriangulation::vertices) lies
// in the inner box, the global dual the others, but no triangle sharing a
// directed edge with one already taken (the same triangle from both grids,
// or near-cocircular seeds split the other way), and where that leaves a gap
// within `seam_cells` global cells of the box's edge, the other grid's
// triangles there; conforming_triangulation then checks the union (and fills
// what still disagrees).
#include <Eigen/Core>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "voronoi/voronoi_problem.h"

namespace homesh {

struct WindowOptions {
  double cells = 6.0;    ///< window grid cells per shortest missed segment, at least
  double finer = 4.0;    ///< window grid spacing at most the global one over this
  int max_nodes = 1200;  ///< window grid nodes along the longer side, at most
  /// Inner box: the missed segments' box grown by this many times the
  /// metric's largest size there (1 / sqrt(lambda_min)); the window's seeds
  /// and grid reach as far again beyond it.
  double pad = 2.0;
  /// Seam: where a triangle of neither dual (or of both) sits within this
  /// many global cells of the inner box's edge, the other grid's is tried.
  double seam_cells = 3.0;
};

/// Boundary segments (seed pairs) that are an edge of no triangle.
std::vector<std::array<int, 2>> missed_segments(const std::vector<std::array<int, 2>>& segments,
                                                const std::vector<std::array<int, 3>>& triangles);

struct RegrownDual {
  Eigen::Matrix2Xd seeds;                     ///< the input seeds, then those the windows added
  std::vector<std::array<int, 3>> triangles;  ///< the merged dual
  int windows = 0;                            ///< windows merged
  int window_nodes = 0;                       ///< grid nodes of the largest window (per side)
  int finer_windows = 0;                      ///< regrowths twice as fine (segments still missed)
};

/// problem: the global problem (its metric field; seed_metrics are not
/// used), its seeds those of `triangles` (2 by S) and
/// its dual `triangles` with their Voronoi vertices `vertices` (2 by T).
/// segments: the boundary seed pairs; domain_on: the domain's level set on
/// any grid (as VoronoiProblem::domain). The missed segments are clustered
/// (those within 2 pads of each other share a window), each cluster's window
/// regrown by refine_dual with `engine`, again twice as fine while some of
/// the cluster's segments are still missed and the node cap allows (the
/// attempt missing the fewest is kept, the finer on a tie), and the duals
/// merged as above. Windows no finer than the global grid are not grown.
RegrownDual regrow_windows(const VoronoiProblem& problem,
                           const std::vector<std::array<int, 3>>& triangles,
                           const Eigen::Matrix2Xd& vertices,
                           const std::vector<std::array<int, 2>>& segments,
                           const std::function<Eigen::VectorXd(const CartesianGrid&)>& domain_on,
                           const std::string& engine, const WindowOptions& options = {});

}  // namespace homesh
