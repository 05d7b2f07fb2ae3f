#pragma once
// Gmsh post-processing views on the current model -> core fields, for writing
// a model's views in a format other than `.msh` (io/write_vtu.h).
#include <vector>

#include "core/field.h"
#include "core/mesh.h"

namespace homesh::gmsh_adapter {

/// The scalar model-based views of the current model (first step) as fields
/// over the triangles of `mesh`, which read_model read from the same model
/// (`triangle_tags`: the Gmsh tag of each triangle, from read_model). Each
/// view is named as in Gmsh (View[i].Name). ElementData becomes an Element
/// field, ElementNodeData an ElementNode field (values in the element's node
/// order, Gmsh's as homesh's), NodeData an ElementNode field of the values
/// at each triangle's nodes. A view's values on other elements (lines,
/// points) are left out, and a triangle it has no value for gets NaN. Views
/// with no value on any triangle, list-based views (.pos) and views of more
/// than one component are skipped.
std::vector<Field> read_views(const Mesh& mesh, const std::vector<std::size_t>& triangle_tags);

}  // namespace homesh::gmsh_adapter
