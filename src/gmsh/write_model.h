#pragma once
// Core mesh -> Gmsh model.
#include <cstddef>
#include <vector>

#include "core/mesh.h"

namespace homesh::gmsh_adapter {

/// Element tags given to the mesh written into the model: point elements get
/// 1.., lines next, the 2D elements last (Mesh::triangle_tag).
struct ModelTags {
  std::size_t first_line = 1;
  /// The tag after the lines': the first 2D element's.
  std::size_t first_triangle = 1;
  /// #2D elements tag of each (triangles, then quadrilaterals: core/mesh.h).
  std::vector<std::size_t> element;
  /// Number of triangles (2D element e is a quadrilateral from there on).
  int triangles = 0;
};

/// Replaces the mesh of the current Gmsh model with `m`. Gmsh 4.8 has no bulk
/// setNodes, so the model's mesh is cleared and nodes/elements are re-added per
/// entity. Entities and physical groups already in the model are kept; those of
/// `m` the model lacks are added (as discrete entities). Node i gets tag i + 1.
ModelTags write_model(const Mesh& m);

}  // namespace homesh::gmsh_adapter
