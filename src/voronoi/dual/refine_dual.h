#pragma once
// The dual checked before use: where check_dual finds a fault, a seed is added at the offending
// triple point and the crystals are grown again, a bounded number of rounds. A seed at a Voronoi
// vertex is equidistant from the seeds that meet there (the circumcentre of
// their triangle in the metric), so it splits a near-degenerate vertex into
// well-separated ones, as Delaunay refinement does (Chew 1989, Ruppert 1995).
#include <Eigen/Core>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "voronoi/dual/voronoi_delaunay.h"

namespace homesh {

struct RefineOptions {
  int max_rounds = 3;  ///< growths after the first, at most
  /// A seed is added only this many cells (ds) away from every seed, every
  /// other seed added in the round and the domain boundary.
  double clearance_cells = 2.0;
  /// Boundary segments (seed pairs) whose diametral circle takes no added
  /// seed (boundary_encroachment.h): such a seed would take the segment out
  /// of the dual.
  std::vector<std::array<int, 2>> segments;
  /// ... and none within this many cells outside it: the triple point of
  /// the segment's ends and a seed just outside the circle lies a fraction of
  /// that inside the wall, closer than a grid resolves (docs/voronoi.md).
  double circle_cells = 0.5;
  /// Where a seed may be added (empty: anywhere), e.g. well inside a window
  /// (window_regrowth.h), whose triangles near its edge give way to the
  /// global dual's.
  std::function<bool(const Eigen::Vector2d&)> allowed;
};

struct RefinedDual {
  VoronoiDelaunay result;  ///< of the last growth
  Eigen::Matrix2Xd seeds;  ///< the problem's seeds, then those added (2 by S)
  std::vector<int> added;  ///< seeds added before each regrowth
  /// The last dual passes check_dual (orphan slivers and isolated regions
  /// are reported in result.regions, not repaired).
  bool ok() const { return result.check.ok(); }
};

/// The points where the dual of `v` fails: the Voronoi vertices of
/// check.bad_triangles, dual.defects and the midpoints of the seeds of
/// check.lone_edges (2 by #faults).
Eigen::Matrix2Xd dual_faults(const Eigen::Matrix2Xd& seeds, const VoronoiDelaunay& v);

/// voronoi_delaunay(problem, engine, options); while its check fails and
/// rounds are left, the faults with clearance become seeds (with
/// seed_metrics: the metric of the seed whose region holds them) and the
/// crystals grow again. Stops early if no fault can take a seed.
RefinedDual refine_dual(VoronoiProblem problem, const std::string& engine = "fast_marching",
                        const VoronoiOptions& options = {}, const RefineOptions& refine = {});

}  // namespace homesh
