#pragma once
#include "pipeline/stage.h"

namespace homesh {

/// `curve`: order p with boundary nodes on the CAD and the interior moved by
/// the augmented elastic analogy, certified valid.
Stage curve_stage();

}  // namespace homesh
