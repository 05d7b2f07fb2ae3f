#pragma once
// The crystal-growth engines, chosen by name: one table drives the CLI choice,
// the Python API and the test loops. "level_set" is the faithful engine of
// thesis Chapter 2; "fast_marching" the fast one Section 2.8 suggests.
#include <string>
#include <vector>

#include "voronoi/engines/voronoi_problem.h"

namespace homesh {

using VoronoiEngineRun = CrystalPartition (*)(const VoronoiProblem& problem,
                                              const VoronoiOptions& options);

struct VoronoiEngine {
  std::string name;  ///< "level_set", "fast_marching"
  std::string help;  ///< one line for listings
  VoronoiEngineRun run;
};

/// All engines.
const std::vector<VoronoiEngine>& voronoi_engines();

/// The engine called `name`. Throws homesh::Error naming it and listing the
/// valid names if there is none.
const VoronoiEngine& voronoi_engine(const std::string& name);

/// voronoi_engine(engine).run(problem, options).
CrystalPartition grow_crystals(const VoronoiProblem& problem,
                               const std::string& engine = "level_set",
                               const VoronoiOptions& options = {});

}  // namespace homesh
