#pragma once
#include "pipeline/stage.h"

namespace homesh {

/// `optimise`: the high-order mesh optimiser (curving/optimise_mesh.h) on the
/// current curved mesh, every node on a model point or curve held. Logs the
/// worst certified minJ/maxJ before and after and the wall time; ctx.results
/// gets worst_before, worst_after, patches, accepted, poor_before, poor_after
/// and seconds. Its option defaults are OptimiseOptions' own.
Stage optimise_stage();

}  // namespace homesh
