#pragma once
// Gmsh post-processing views on the current model -> core fields, for writing
// a model's views in a format other than `.msh` (io/write_vtu.h).
#include <vector>

#include "core/field.h"
#include "core/mesh.h"

namespace homesh::gmsh_adapter {

/// The scalar model-based views of the current model (first step) as fields
/// over the 2D elements of `mesh` (triangles, then quadrilaterals), which
/// read_model read from the same model (`element_tags`: the Gmsh tag of each
/// 2D element, from read_model). Each view is named as in Gmsh
/// (View[i].Name). ElementData becomes an Element field, ElementNodeData an
/// ElementNode field (values in the element's node order, Gmsh's as
/// homesh's; rows as core/field.h says), NodeData an ElementNode field of the
/// values at each element's nodes. A view's values on other elements (lines,
/// points) are left out, and an element it has no value for gets NaN. Views
/// with no value on any 2D element, list-based views (.pos) and views of more
/// than one component are skipped.
std::vector<Field> read_views(const Mesh& mesh, const std::vector<std::size_t>& element_tags);

}  // namespace homesh::gmsh_adapter
