#pragma once
#include "pipeline/stage.h"

namespace homesh {

/// `mesh`: a new linear triangle mesh of the input's CAD by Gmsh.
Stage mesh_stage();

}  // namespace homesh
