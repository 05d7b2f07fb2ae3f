#pragma once
// Elements in the order Gmsh writes them: by entity tag. Gmsh writes a mesh
// entity by entity (points, lines, then each surface's triangles and
// quadrilaterals, by ascending entity tag), and a view's element data in
// element-tag order; homesh tags elements by their position among those of
// their kind, surface by surface (Mesh::triangle_tag). With the elements
// grouped by entity the two orders agree, which meshio needs (it assigns
// element data to the elements in file order, ignoring tags), and Gmsh's own
// tags read back equal homesh's. Stages that append elements (layers on
// several surfaces, voronoi) may leave them interleaved.
#include <vector>

#include "core/mesh.h"

namespace homesh {

/// Reorders m's points, lines, triangles and quadrilaterals stably by entity
/// tag. Returns the permutation of the 2D elements (triangles, then
/// quadrilaterals, as core/mesh.h numbers them), new position -> old (empty if
/// the 2D elements were already grouped).
std::vector<int> group_by_entity(Mesh& m);

}  // namespace homesh
