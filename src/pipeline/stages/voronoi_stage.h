#pragma once
#include <string>

#include "pipeline/stage.h"
#include "voronoi/lloyd_relaxation.h"
#include "voronoi/metric_seeding.h"

namespace homesh {

/// The voronoi stage's options (their meaning: the stage's option help).
struct VoronoiStageOptions {
  std::string metric = "iso";            ///< iso, bl, viewN or a file
  std::string seeds = "auto";            ///< auto or a file of interior seeds
  SeedingOptions seeding;                ///< front_rows: all
  LloydOptions lloyd;                    ///< iterations: 10
  int smooth = 3;                        ///< smoothing sweeps (voronoi/metric_smoothing.h)
  std::string engine = "fast_marching";  ///< a name of voronoi_engines()
  int grid = 0;                          ///< grid nodes along the longer side; 0: automatic
};

/// `voronoi`: a new linear triangle mesh of the input's CAD, dual to the
/// crystal-growth Voronoi diagram of thesis Chapter 2 (replaces any mesh).
Stage voronoi_stage();

}  // namespace homesh
