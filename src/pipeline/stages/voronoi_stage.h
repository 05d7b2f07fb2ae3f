#pragma once
#include <string>

#include "pipeline/stage.h"
#include "voronoi/metric/size_metric.h"
#include "voronoi/voronoi_mesh.h"

namespace homesh {

/// The voronoi stage's options (their meaning: the stage's option help): the
/// mesher's own (voronoi_mesh) and what the stage makes of the model.
struct VoronoiStageOptions {
  std::string metric = "iso";  ///< iso, bl, viewN or a file
  std::string seeds = "auto";  ///< auto or a file of interior seeds
  double factor = 0;           ///< on the sizes of Gmsh's mesh (0: Mesh.MeshSizeFactor's)
  BoundaryLayerOptions layer;  ///< of metric=bl
  VoronoiMeshOptions mesher;
};

/// `voronoi`: a new linear triangle mesh of the input's CAD, dual to the
/// crystal-growth Voronoi diagram of thesis Chapter 2 (replaces any mesh).
Stage voronoi_stage();

}  // namespace homesh
