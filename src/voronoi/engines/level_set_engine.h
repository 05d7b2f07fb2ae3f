#pragma once
// The faithful engine of thesis Chapter 2: one level set per seed advanced by
// the explicit upwind scheme of Eqs 2.2-2.5 (voronoi/engines/level_set_crystal.h) with
// dt = cfl ds / max F (Section 2.3), collisions found along the grid lines and
// frozen (Eqs 2.9-2.12), and the domain boundary as a stationary crystal met
// wet (Eqs 2.9-2.12) or dry (Eq 2.13).
#include "voronoi/engines/voronoi_problem.h"

namespace homesh {

/// Grows one crystal per seed until the grid (or domain) is filled or no front
/// has moved onto a new node for as long as the slowest front needs to cross a
/// cell twice (or options.max_steps / stop_time). Labels: the crystal holding
/// each node (phi_s <= 0); once settled, a node left between frozen fronts
/// takes the crystal of smallest phi_s (all phi_s are metric distances minus
/// the same time, so comparable). Throws homesh::Error
/// for no seeds, a seed outside the grid, or per-seed metrics of the wrong
/// count.
CrystalPartition grow_crystals_level_set(const VoronoiProblem& problem,
                                         const VoronoiOptions& options);

}  // namespace homesh
