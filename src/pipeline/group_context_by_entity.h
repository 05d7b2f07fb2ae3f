#pragma once
// After a stage: the context's mesh grouped by entity (core/group_by_entity.h),
// its fields' columns permuted with the triangles, so the element tags every
// later report gives are those of the written file, and meshio reads the
// file's element data onto the right elements.
#include "pipeline/context.h"

namespace homesh {

/// Groups ctx.mesh (if any) by entity and permutes ctx.fields to match.
void group_context_by_entity(Context& ctx);

}  // namespace homesh
