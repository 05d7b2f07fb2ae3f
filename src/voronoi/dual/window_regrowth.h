#pragma once
// A finer grid where the global one is too coarse for the seeds. Where the
// crystal dual misses boundary segments (seeds a cell or two apart, as at a
// sharp trailing edge), and round seeds known to be finer than the global
// grid resolves (a global grid sized for most of the domain, not for its
// finest spot), the crystals round the spot grow again on a grid over
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

#include "voronoi/engines/voronoi_problem.h"

namespace homesh {

struct WindowOptions {
  double cells = 6.0;  ///< window grid cells per shortest missed segment, at least
  /// window grid spacing at most the global one over this, where a segment
  /// with `cells` global cells along it was missed
  double finer = 4.0;
  int max_nodes = 1200;  ///< window grid nodes along the longer side, at most
  double min_ds = 0.0;   ///< window grid spacing at least this
  /// Inner box: the missed segments' box grown by this many times the
  /// metric's largest size there (1 / sqrt(lambda_min)); the window's seeds
  /// and grid reach as far again beyond it.
  double pad = 2.0;
  /// Seam: where a triangle of neither dual (or of both) sits within this
  /// many global cells of the inner box's edge, the other grid's is tried.
  double seam_cells = 3.0;
};

/// Clusters of points: those within `reach` times the larger of their two
/// sizes of each other (transitively) share one. The members of each
/// (indices, ascending), the clusters in the order of their first member.
std::vector<std::vector<int>> cluster_spots(const std::vector<Eigen::Vector2d>& points,
                                            const std::vector<double>& sizes, double reach);

/// Boundary segments (seed pairs) that are an edge of no triangle.
std::vector<std::array<int, 2>> missed_segments(const std::vector<std::array<int, 2>>& segments,
                                                const std::vector<std::array<int, 3>>& triangles);

struct RegrownDual {
  Eigen::Matrix2Xd seeds;                     ///< the input seeds, then those the windows added
  std::vector<std::array<int, 3>> triangles;  ///< the merged dual
  Eigen::Matrix2Xd vertices;                  ///< their Voronoi vertices (2 by T)
  int windows = 0;                            ///< windows merged
  int window_nodes = 0;                       ///< grid nodes of the largest window (per side)
  int finer_windows = 0;                      ///< regrowths twice as fine (segments still missed)
};

/// problem: the global problem (its metric field; seed_metrics are not
/// used), its seeds those of `triangles` (2 by S) and
/// its dual `triangles` with their Voronoi vertices `vertices` (2 by T).
/// segments: the boundary seed pairs; domain_on: the domain's level set on
/// any grid (as VoronoiProblem::domain); fine: seeds (ascending) whose
/// spacing, the smallest semi-axis of the metric there, the global grid does
/// not resolve. The missed segments, or if there are fine seeds these alone
/// (call again for the segments still missed), are clustered
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
                           const std::string& engine, const WindowOptions& options = {},
                           const std::vector<int>& fine = {});

}  // namespace homesh
