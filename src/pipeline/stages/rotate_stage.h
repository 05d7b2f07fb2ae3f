#pragma once
#include "pipeline/stage.h"

namespace homesh {

/// `rotate`: the rotation benchmark of thesis Section 4.4 on the current mesh:
/// the curves of a physical group turn rigidly step by step, the interior
/// follows the elastic analogy, until the first step that would make an
/// element invalid; the output is the last valid state, and theta_max, steps,
/// mean CG iterations and the worst minJ/maxJ go to the log and ctx.results.
Stage rotate_stage();

}  // namespace homesh
