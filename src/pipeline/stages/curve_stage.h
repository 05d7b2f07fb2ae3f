#pragma once
#include "pipeline/stage.h"

namespace homesh {

/// `curve`: order p with boundary nodes on the CAD and the interior moved by
/// the augmented elastic analogy, certified valid. Without CAD (a bare .msh)
/// the boundary nodes go onto cubic splines rebuilt from the linear boundary
/// (curving/boundary_reconstruction.h), vertices turning more than `corner`
/// degrees kept sharp; the log says so and ctx.results records
/// boundary_rebuilt = 1 with corner_degrees and the chain counts.
Stage curve_stage();

}  // namespace homesh
