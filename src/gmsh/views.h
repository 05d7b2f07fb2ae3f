#pragma once
// Core fields -> Gmsh post-processing views on the current model.
#include <vector>

#include "core/field.h"
#include "gmsh/write_model.h"

namespace homesh::gmsh_adapter {

/// Adds one view per field on the triangles written by write_model (tags from
/// `tags`), as ElementData or ElementNodeData. Returns the view tags.
std::vector<int> add_views(const std::vector<Field>& fields, const ModelTags& tags);

}  // namespace homesh::gmsh_adapter
