#pragma once
// The whole of thesis Chapter 2 in one call: grow the crystals, read the
// regions off the labels, build the dual Delaunay triangulation and check it.
#include <string>

#include "voronoi/dual/check_dual.h"
#include "voronoi/dual/dual_triangulation.h"
#include "voronoi/dual/region_analysis.h"
#include "voronoi/engines/voronoi_problem.h"

namespace homesh {

struct VoronoiDelaunay {
  CrystalPartition partition;
  RegionReport regions;
  DualTriangulation dual;
  DualCheck check;

  /// A valid dual: settled, no orphan, isolated or missing region, every
  /// domain node reached, and check.ok().
  bool valid() const {
    return partition.settled && regions.orphans.empty() && regions.isolated.empty() &&
           regions.missing.empty() && regions.unreached == 0 && check.ok();
  }
};

/// Runs the engine called `engine` (voronoi_engines.h) on `problem`, then
/// analyse_regions, dual_triangulation (collisions and region adjacencies,
/// in-circle tests in problem.metric) and check_dual.
VoronoiDelaunay voronoi_delaunay(const VoronoiProblem& problem,
                                 const std::string& engine = "level_set",
                                 const VoronoiOptions& options = {});

}  // namespace homesh
