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
// Before it, by default and where the metric is isotropic everywhere,
// lattices: breadth first from the seeds given, each
// seed throws its first candidates at the six directions of a hexagonal
// lattice of unit metric edges (in the unit ball of M there), turned as the
// edge from its parent, so that the lattice of the front rows carries on
// inwards; the frontal point insertion of Gmsh's packing of parallelograms
// with six directions in place of a cross field's four (Baudouin, Remacle,
// Marchandise, Henrotte and Geuzaine, "A frontal approach to hex-dominant
// mesh generation", Adv Model Simul Eng Sci 1:8, 2014). Random seeding
// leaves a defect (a node of valence 5 or 7) wherever discs happen to pack
// badly; lattices leave them only where they meet.
//
// Seed count: the hexagonal lattice of unit metric edges has 2 / sqrt(3) =
// 1.155 nodes per unit metric area (integral of sqrt(det M) dA); a maximal
// Poisson-disc sample of spacing s about 0.70 / s^2 (the random sequential
// adsorption coverage 0.547 of discs of diameter s), so s = 0.8 gives ~94 %
// of the lattice's count, 0.85 only ~83 % (docs/voronoi.md: measured).
#include <Eigen/Core>
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "voronoi/grid/cartesian_grid.h"
#include "voronoi/metric/metric_field.h"

namespace homesh {

/// front_rows: rows until the fronts meet.
constexpr int kAllFrontRows = std::numeric_limits<int>::max();

struct SeedingOptions {
  double spacing = 0.8;            ///< smallest metric distance between seeds
  double annulus = 0.3;            ///< candidates up to spacing (1 + annulus) away
  double boundary_gap = 0.7;       ///< smallest metric distance to the boundary
  int tries = 24;                  ///< candidates per seed before it retires
  double front_spacing = 0.75;     ///< smallest metric distance of a front seed to any other
  int front_rows = kAllFrontRows;  ///< rows of the advancing front (metric_front_seeds)
  /// Columns across anisotropic walls (column_seeds.h): from the boundary
  /// seeds where the metric is at least this anisotropic (ratio of its
  /// semi-axes; 0: no columns) ...
  double column_anisotropy = 2.0;
  double column_end = 1.5;  ///< ... up to where it is less than this
  double column_turn = 30;  ///< ... and where the wall turns by less (degrees)
  /// The seeds where the front rows and columns leave off | lattice:
  /// hexagonal lattices of unit metric edges grown breadth first from the
  /// seeds before them, then Poisson-disc seeds in the gaps where they meet,
  /// where the metric is isotropic everywhere (Poisson-disc seeds elsewhere)
  /// | poisson: Poisson-disc seeds only. On the corpus (docs/voronoi.md) the
  /// lattice leaves fewer interior nodes of valence other than 6 (11 % against
  /// 19 % on the plate at 3e4 triangles), which keeps the mean shape at or
  /// above Gmsh frontal's where Poisson-disc seeds fell below it from 2.5e4
  /// triangles.
  std::string interior = "lattice";
  unsigned random_seed = 1;  ///< std::mt19937, so the seeds are reproducible
};

/// grid and domain: as in VoronoiProblem (domain < 0 inside, a signed
/// distance near the boundary; empty: the whole grid box); boundary_seeds:
/// 2 by B, kept and spaced from. Returns the interior seeds (2 by n).
Eigen::Matrix2Xd metric_interior_seeds(const CartesianGrid& grid, const Eigen::VectorXd& domain,
                                       const MetricField& metric,
                                       const Eigen::Matrix2Xd& boundary_seeds,
                                       const SeedingOptions& options = {});

/// The first row of an advancing front, as seeds (Rebay, "Efficient
/// unstructured mesh generation by means of Delaunay triangulation and
/// Bowyer-Watson algorithm", J Comput Phys 106, 1993, the frontal point
/// placement Gmsh's Frontal-Delaunay mesher uses): for each boundary segment
/// (a, b) of `segments` (indices into boundary_seeds, the domain on the left),
/// the point q on its bisector in the metric, above the midpoint m by
///
///   q = m + t n / |n|_M(q),  n = M^-1/2 R90 M^1/2 (b - a) (the left normal
///   in the metric M at m),  t = sqrt(1 - L^2 / 4),  L = |b - a|_M(q),
///
/// so that the sides (a, q) and (b, q) have unit length in the metric at q
/// (the segment's apex in a graded metric lies where that metric is), with t
/// kept within 0.6 to 1.5 times the equilateral height sqrt(3)/2 L (three
/// fixed-point steps for q). The segments are taken in their order; q is kept
/// if its metric ball of radius options.boundary_gap lies in the domain and it
/// is at least options.front_spacing (metric length) from every boundary seed
/// and every front seed kept before it. Along a straight boundary of unit
/// segments the seeds make a row of equilateral triangles with it, where
/// Poisson-disc seeds leave the boundary's triangles at random shapes.
/// Returns the front seeds (2 by n), to be placed before (and spaced from by)
/// metric_interior_seeds.
struct FrontSeeds {
  Eigen::Matrix2Xd seeds{2, 0};  ///< row by row
  Eigen::Index first_row = 0;    ///< the first row's count (they come first)
};
FrontSeeds metric_front_seeds(const CartesianGrid& grid, const Eigen::VectorXd& domain,
                              const MetricField& metric, const Eigen::Matrix2Xd& boundary_seeds,
                              const std::vector<std::array<int, 2>>& segments,
                              const SeedingOptions& options = {});

}  // namespace homesh
