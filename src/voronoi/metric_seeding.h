#pragma once
// Interior seeds that conform to a metric field: Poisson-disc sampling
// (Bridson, "Fast Poisson disk sampling in arbitrary dimensions", SIGGRAPH
// sketches 2007) carried out in the metric. From every seed placed (the
// boundary seeds first), candidates are thrown at metric distances in
// [spacing, spacing * (1 + annulus)] in random directions of the unit ball of
// the metric there; a candidate is kept if its metric ball of radius
// `boundary_gap` lies in the domain (tested at 16 points of its boundary) and
// it is at least `spacing` (metric length, mean of the two points' metrics)
// from every seed. The result is a well-spaced point set whose spacing
// follows the metric: edges of its metric Delaunay triangulation have metric
// lengths between `spacing` and about 2 `spacing`.
//
// Seed count: the hexagonal lattice of unit metric edges has 2 / sqrt(3) =
// 1.155 nodes per unit metric area (integral of sqrt(det M) dA); a maximal
// Poisson-disc sample of spacing s about 0.70 / s^2 (the random sequential
// adsorption coverage 0.547 of discs of diameter s), so s = 0.8 gives ~94 %
// of the lattice's count, 0.85 only ~83 % (docs/voronoi.md: measured).
#include <Eigen/Core>

#include "voronoi/cartesian_grid.h"
#include "voronoi/metric_field.h"

namespace homesh {

struct SeedingOptions {
  double spacing = 0.8;       ///< smallest metric distance between seeds
  double annulus = 0.3;       ///< candidates up to spacing (1 + annulus) away
  double boundary_gap = 0.7;  ///< smallest metric distance to the boundary
  int tries = 24;             ///< candidates per seed before it retires
  unsigned random_seed = 1;   ///< std::mt19937, so the seeds are reproducible
};

/// grid and domain: as in VoronoiProblem (domain < 0 inside, a signed
/// distance near the boundary; empty: the whole grid box); boundary_seeds:
/// 2 by B, kept and spaced from. Returns the interior seeds (2 by n).
Eigen::Matrix2Xd metric_interior_seeds(const CartesianGrid& grid, const Eigen::VectorXd& domain,
                                       const MetricField& metric,
                                       const Eigen::Matrix2Xd& boundary_seeds,
                                       const SeedingOptions& options = {});

}  // namespace homesh
