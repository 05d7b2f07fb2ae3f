#pragma once
// Elements in the order Gmsh writes them: by entity tag. Gmsh writes a mesh
// entity by entity (points, lines, triangles, each by ascending entity tag),
// and a view's element data in element-tag order; homesh tags elements by
// their position (Mesh::triangle_tag). With the elements grouped by entity the
// two orders agree, which meshio needs (it assigns element data to the
// elements in file order, ignoring tags), and Gmsh's own tags read back equal
// homesh's. Stages that append elements (layers on several surfaces,
// voronoi) may leave them interleaved.
#include <vector>

#include "core/mesh.h"

namespace homesh {

/// Reorders m's points, lines and triangles stably by entity tag. Returns the
/// triangle permutation, new position -> old (empty if m was already grouped).
std::vector<int> group_by_entity(Mesh& m);

}  // namespace homesh
