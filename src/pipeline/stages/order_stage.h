#pragma once
#include "pipeline/stage.h"

namespace homesh {

struct OrderOptions {
  int order = 2;  ///< p, 1 to kMaxOrder (core/raise_order.h)
};

/// `order`: the mesh at order p with straight-sided elements.
Stage order_stage();

}  // namespace homesh
