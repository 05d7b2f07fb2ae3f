#pragma once
// Core fields -> Gmsh post-processing views on the current model.
#include <vector>

#include "core/field.h"
#include "gmsh/write_model.h"

namespace homesh::gmsh_adapter {

/// Adds one view per field, named after it, on the mesh written by
/// write_model (tags from `tags`), and styles it (gmsh/view_style.h); if a
/// field is shown, every view added before is hidden. Returns the view tags.
/// An Element field is ElementData over every element of the model, points
/// and lines included with a neutral value (1 for a quality, 0 otherwise):
/// meshio reads element data only if it covers every element, in the order of
/// the file. An ElementNode field is ElementNodeData over the triangles and
/// quadrilaterals (meshio skips it).
std::vector<int> add_views(const std::vector<Field>& fields, const ModelTags& tags);

}  // namespace homesh::gmsh_adapter
