#pragma once
#include "pipeline/stage.h"

namespace homesh {

/// `voronoi`: a new linear triangle mesh of the input's CAD, dual to the
/// crystal-growth Voronoi diagram of thesis Chapter 2 (replaces any mesh).
Stage voronoi_stage();

}  // namespace homesh
