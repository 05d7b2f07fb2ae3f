#pragma once
// The crystal-growth Voronoi mesher of thesis Chapter 2 as one library call:
// seeds placed in the metric (front rows, Poisson-disc, Lloyd's iteration),
// crystals grown as level sets in the Riemannian metric (Sections 2.3-2.4),
// the dual Delaunay triangulation with its refinement and regrowth where it
// misses the boundary (Section 2.5), a constrained fill where it still does
// not conform, and smoothing of the interior nodes. Gmsh-free: the boundary
// comes sampled and seeded (gmsh/boundary_sampling.h makes it from the CAD).
#include <string>
#include <vector>

#include "core/mesh.h"
#include "voronoi/grid/cartesian_grid.h"
#include "voronoi/metric/metric_field.h"
#include "voronoi/seeding/lloyd_relaxation.h"
#include "voronoi/seeding/metric_seeding.h"
#include "voronoi/seeding/seeded_boundary.h"
#include "voronoi/voronoi_files.h"

namespace homesh {

/// Every default of the mesher (the voronoi stage's options map onto these).
struct VoronoiMeshOptions {
  SeedingOptions seeding;  ///< automatic seeds: front rows, Poisson-disc
  LloydOptions lloyd;      ///< on the automatic seeds (front rows held)
  /// Smoothing sweeps (voronoi/cleanup/metric_smoothing.h) after the dual and after each
  /// clean-up step. 3 until 4 Dec 2026: 2 took 0.95x the stage's time on the corpus
  /// (median, same hour), its worst shape at most 0.008 below 3's (0.05 above on others),
  /// the mean within 0.0008,
  /// and metric=bl's curved worst at p = 3 the same on 23 of 24 models (0.900 -> 0.899).
  int smooth = 2;
  /// After the smoothing and the flips, at most this many steps raising the
  /// mesh's worst triangle (raise_worst_triangle in metric_smoothing.h; on
  /// the corpus it stops within 50): the minimum up by 0.013 (median, up to
  /// 0.055), the mean within 0.0023 (docs/voronoi.md).
  int raise_worst = 100;
  /// Topological clean-up of the dual: interior nodes of three triangles
  /// removed (voronoi/cleanup/valence_three.h), edges flipped where that raises the
  /// worst mean ratio (Q11) in the metric, after the smoothing; interior nodes
  /// of four triangles removed where their quad is better without them
  /// (valence_four.h); edges flipped towards valence 6 (valence_flips.h).
  bool cleanup = true;
  /// The triangulation the clean-up starts from | grown: the dual of the
  /// crystals grown on the grid (thesis Ch 2) | exact: the Delaunay
  /// triangulation of the seeds (CGAL), dual to their Euclidean Voronoi
  /// cells, the crystals of a locally constant isotropic metric; where the
  /// metric is anisotropic, made Delaunay in it by Lawson's flips
  /// (metric_delaunay.h), the dual of their Voronoi cells in the metric of
  /// each quad. On NACA-7526 with metric=bl, 5:1 to 1000:1 (docs/voronoi.md)
  /// exact made no fill and curved to p = 3 at 0.977-0.984, grown filled
  /// triangles from 10:1 and could not go past 20:1.
  std::string dual = "exact";
  std::string engine = "fast_marching";  ///< a name of voronoi_engines()
  /// Grid nodes along a surface's longer side; 0: its smallest size over 6
  /// cells for the grown dual, over 2 for the exact one (whose grid serves only
  /// the seeds' inside tests), 200 to 1500 nodes.
  int grid = 0;
  /// With grid = 0: the crystals grow on a grid sized for all but the finer
  /// half of the seeds, and again on finer grids in windows round those
  /// (window_regrowth.h), where one grid for the finest spot of a far field
  /// costs (largest / smallest size)^2 times the nodes.
  bool fine_windows = true;
  /// Interior seeds from a file instead of the automatic ones (path: for
  /// messages); every seed must lie in some surface.
  const SeedList* seed_list = nullptr;
  std::string seed_path;
};

/// What the mesher did on one surface.
struct VoronoiSurfaceReport {
  int tag = -1;
  CartesianGrid grid;    ///< of the growth (seeding: finer if fine_seeds > 0)
  long fine_seeds = 0;   ///< seeds finer than the growth grid resolves, grown in windows
  int fine_windows = 0;  ///< windows round them (of `windows`)
  long boundary_seeds = 0, front_seeds = 0, interior_seeds = 0;  ///< front: columns and rows
  long column_seeds = 0;             ///< in columns across anisotropic walls (column_seeds.h)
  int columns = 0, column_rows = 0;  ///< columns started, seeds in the longest
  long encroaching_dropped = 0;      ///< automatic seeds in a boundary segment's diametral circle
  bool exact_lloyd = false;          ///< Lloyd's iteration on exact cells (exact_lloyd.h)
  int lloyd_iterations = 0;          ///< its iterations (at most: exact cells stop once still)
  bool exact_dual = false;           ///< the seeds' Delaunay triangulation, no growth
  bool metric_dual = false;  ///< ... made Delaunay in an anisotropic metric (metric_delaunay.h)
  int metric_flips = 0;      ///< by these flips
  double seeding_seconds = 0, growth_seconds = 0;
  long dual_size = 0;         ///< triangles of the first dual
  bool dual_checked = false;  ///< the refined dual passed check_dual
  long refinement_rounds = 0;
  long refined_seeds = 0;    ///< seeds added at faulty triple points
  long missed_segments = 0;  ///< boundary segments the dual missed before regrowth
  int windows = 0, window_nodes = 0, finer_windows = 0;
  long regrown_seeds = 0;
  long segments = 0, boundary_missed = 0, dual_dropped = 0;  ///< after regrowth
  long from_dual = 0, filled = 0;                            ///< triangles of the result by origin
};

/// What the mesher did, for the log and the stage's results.
struct VoronoiReport {
  std::vector<VoronoiSurfaceReport> surfaces;
  int dual_triangles = 0;    ///< triangles from the dual
  int filled_triangles = 0;  ///< triangles of the constrained fill (CGAL)
  int refined_seeds = 0;     ///< seeds added at faulty triple points
  int dropped_seeds = 0;     ///< interior seeds cut off by a boundary chord
  int smoothing_moves = 0;
  int valence_three = 0;  ///< interior nodes of three triangles removed
  int valence_four = 0;   ///< interior nodes of four triangles removed (valence_four.h)
  int valence_flips = 0;  ///< edges flipped towards valence 6 (valence_flips.h)
  int flips = 0;          ///< edges flipped
  int raise_steps = 0;    ///< steps raising the worst triangle (raise_worst_triangle)
  /// The result's mean ratio (Q11) in the metric at each centroid: 1 for a
  /// triangle equilateral in it.
  double metric_quality_min = 0, metric_quality_mean = 0;
};

/// A linear triangle mesh of the surfaces of `boundary` (nodes: the boundary
/// seeds first, in order, classified as boundary.classes; then the interior
/// nodes, classified on their surface; lines: the boundary seeds' segments of
/// each curve, tagged by curve; points: the seeds on model points), dual to
/// the crystal-growth Voronoi diagram of its seeds in `metric`. The mesh's
/// entities and physical groups are left empty for the caller. Throws
/// homesh::Error naming the seed file for a seed outside every surface or too
/// close to the boundary or another seed.
Mesh voronoi_mesh(const SeededBoundary& boundary, const MetricField& metric,
                  const VoronoiMeshOptions& options = {}, VoronoiReport* report = nullptr);

}  // namespace homesh
