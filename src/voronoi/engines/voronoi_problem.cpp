#include "voronoi/engines/voronoi_problem.h"

#include <string>

#include "core/error.h"

namespace homesh {

void check_domain_size(const VoronoiProblem& problem) {
  const Eigen::Index n = problem.grid.node_count(), d = problem.domain.size();
  if (d != 0 && d != n)
    throw Error("voronoi: domain has " + std::to_string(d) + " values for " + std::to_string(n) +
                " grid nodes");
}

}  // namespace homesh
