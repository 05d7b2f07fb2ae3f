#include "voronoi/dual/voronoi_delaunay.h"

#include "voronoi/engines/voronoi_engines.h"

namespace homesh {

VoronoiDelaunay voronoi_delaunay(const VoronoiProblem& problem, const std::string& engine,
                                 const VoronoiOptions& options) {
  VoronoiDelaunay out;
  out.partition = grow_crystals(problem, engine, options);
  out.regions = analyse_regions(problem.grid, out.partition.labels, problem.seeds, problem.domain);
  out.dual = dual_triangulation(problem.grid, out.partition.labels, problem.seeds,
                                out.partition.collisions, out.regions.adjacent, problem.metric);
  out.check = check_dual(problem.seeds, out.dual, out.regions);
  return out;
}

}  // namespace homesh
