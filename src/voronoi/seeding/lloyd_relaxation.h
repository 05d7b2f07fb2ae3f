#pragma once
// Lloyd's iteration on the crystal regions: each free seed moves to the
// centroid of its grown region, the crystals grow again, a few times. Its
// fixed points are centroidal Voronoi tessellations (Du, Faber, Gunzburger,
// "Centroidal Voronoi tessellations: applications and algorithms", SIAM
// Review 41(4), 1999), whose dual triangles are close to equilateral in the
// metric; the Poisson-disc seeds of metric_seeding.h are only well spaced.
//
// Anisotropic centroid (after Du & Wang, "Anisotropic centroidal Voronoi
// tessellations and their applications", SIAM J Sci Comput 26(3), 2005,
// with the distance measured in the metric at the point x): the z that
// minimises the region's energy  sum_x (x - z)^T M(x) (x - z) dA  over its
// grid nodes x is
//
//   z = (sum_x M(x))^-1  sum_x M(x) x,
//
// the plain centroid in a constant metric, weighted by 1/h^2 in the
// isotropic metric M = I / h^2 of a size field h.
#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>
#include <string>
#include <vector>

#include "voronoi/engines/voronoi_problem.h"

namespace homesh {

/// The weight of a point in the centroids above: W = sqrt(det M) M.
inline Eigen::Matrix2d centroid_weight(const Eigen::Matrix2d& M) {
  return std::sqrt(M.determinant()) * M;
}

/// The centroids above of the regions of seeds 0..seeds-1 in `labels`
/// (grid.node_count() crystal ids, -1: none), each region in the metric it
/// grew in (seed_metrics[s] if not empty, else metric). 2 by seeds; NaN for
/// a seed with no node.
Eigen::Matrix2Xd region_centroids(const CartesianGrid& grid, const Eigen::VectorXi& labels,
                                  int seeds, const MetricField& metric,
                                  const std::vector<Eigen::Matrix2d>& seed_metrics = {});

/// LloydOptions::iterations: kExactIterations on exact cells, kGrownIterations
/// on grown ones (each a growth of the crystals on a grid).
constexpr int kAutoIterations = -1;
constexpr int kExactIterations = 10, kGrownIterations = 10;

struct LloydOptions {
  /// Moves of every free seed (0: none), or kAutoIterations: 10 on exact
  /// cells, 10 on grown ones. On the corpus with the exact dual (docs/voronoi.md,
  /// 3 Dec 2026) 30, 15 and 10 exact steps all kept the worst and mean ICN
  /// above Gmsh frontal's on every model (mean margins: median 0.0078,
  /// 0.0062, 0.0054). 15 were the default until 4 Dec 2026; 10 with 2
  /// smoothing sweeps (VoronoiMeshOptions::smooth) took 0.89x the stage's time
  /// (median over the 41 models, same hour), the least margins over frontal
  /// 0.0846 worst, 0.0075 mean (0.0747, 0.0084 with 15 and 3).
  int iterations = kAutoIterations;
  /// A seed moves only if its centroid is this many cells (ds) inside the
  /// domain and from every other seed; otherwise it stays.
  double clearance_cells = 2.0;
  /// The regions the centroids are taken of: "grown" (the crystals on the
  /// grid, as below), "exact" (the seeds' Euclidean Voronoi cells,
  /// exact_lloyd.h, weighted by the metric), or "auto": exact with the exact
  /// dual or where the metric is isotropic everywhere (its semi-axes within
  /// kIsotropic at every node of its coarse grid), else grown.
  std::string cells = "auto";
  /// With exact cells: a centroid is taken only this many sizes inside the
  /// domain and from every neighbour.
  double exact_clearance = 0.25;
};

/// The iterations `o` asks for on exact or grown cells (kAutoIterations
/// resolved).
inline int lloyd_iterations(const LloydOptions& o, bool exact) {
  return o.iterations != kAutoIterations ? o.iterations
         : exact                         ? kExactIterations
                                         : kGrownIterations;
}

/// Throws homesh::Error unless `held` is empty or has one flag per seed.
void check_held(const std::vector<char>& held, Eigen::Index seeds);

/// Semi-axes within this ratio: isotropic, for LloydOptions::cells = "auto".
constexpr double kIsotropic = 1.01;

/// Seeds 0..fixed-1 of `problem` (the boundary seeds) stay, and so does
/// every seed s with held[s] != 0 (held empty or one flag per seed, e.g. the
/// seeds too close together for the grid to give their regions' centroids);
/// the others move to region_centroids of the crystals grown by `engine`,
/// options.iterations times. Returns all the seeds (2 by S, in the
/// problem's order).
Eigen::Matrix2Xd lloyd_relaxation(VoronoiProblem problem, int fixed,
                                  const std::string& engine = "fast_marching",
                                  const LloydOptions& options = {},
                                  const std::vector<char>& held = {});

}  // namespace homesh
