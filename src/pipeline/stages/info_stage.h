#pragma once
#include "pipeline/stage.h"

namespace homesh {

/// `info`: counts, order, entities and physical groups of the mesh.
Stage info_stage();

}  // namespace homesh
