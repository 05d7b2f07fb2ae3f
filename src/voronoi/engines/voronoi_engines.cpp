#include "voronoi/engines/voronoi_engines.h"

#include "core/error.h"
#include "voronoi/engines/fast_marching_engine.h"
#include "voronoi/engines/level_set_engine.h"

namespace homesh {

const std::vector<VoronoiEngine>& voronoi_engines() {
  static const std::vector<VoronoiEngine> engines = {
      {"level_set",
       "one level set per seed, first-order upwind, collisions frozen on grid lines "
       "(thesis Eqs 2.1-2.13)",
       grow_crystals_level_set},
      {"fast_marching",
       "all crystals in one anisotropic fast-marching sweep (FM-LBR stencils), each crystal's "
       "own arrival time kept where crystals meet; O(N log N) in the grid nodes",
       grow_crystals_fast_marching},
  };
  return engines;
}

const VoronoiEngine& voronoi_engine(const std::string& name) {
  std::string names;
  for (const VoronoiEngine& e : voronoi_engines()) {
    if (e.name == name) return e;
    names += (names.empty() ? "" : ", ") + e.name;
  }
  throw Error("unknown Voronoi engine '" + name + "' (choose from: " + names + ")");
}

CrystalPartition grow_crystals(const VoronoiProblem& problem, const std::string& engine,
                               const VoronoiOptions& options) {
  return voronoi_engine(engine).run(problem, options);
}

}  // namespace homesh
