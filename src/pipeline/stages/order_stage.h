#pragma once
#include "pipeline/stage.h"

namespace homesh {

/// `order`: the mesh at order p with straight-sided elements.
Stage order_stage();

}  // namespace homesh
