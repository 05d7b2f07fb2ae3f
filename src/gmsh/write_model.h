#pragma once
// Core mesh -> Gmsh model.
#include <cstddef>
#include <vector>

#include "core/mesh.h"

namespace homesh::gmsh_adapter {

/// Element tags given to the mesh written into the model: point elements get
/// 1.., lines next, the 2D elements last (Mesh::triangle_tag). Of a volume mesh
/// (gmsh/write_volume_model.h) the tetrahedra come last, after the triangles:
/// its fields, and so these tags, are over the tetrahedra.
struct ModelTags {
  std::size_t first_line = 1;
  /// The first tag of the elements fields are over (2D elements, or tetrahedra).
  std::size_t first_triangle = 1;
  /// Tag of each element fields are over (triangles, then quadrilaterals:
  /// core/mesh.h; or tetrahedra).
  std::vector<std::size_t> element;
  /// Number of triangles, or of tetrahedra (element e is a quadrilateral from there on).
  int triangles = 0;
};

/// Replaces the mesh of the current Gmsh model with `m`. Gmsh 4.8 has no bulk
/// setNodes, so the model's mesh is cleared and nodes/elements are re-added per
/// entity. Entities and physical groups already in the model are kept; those of
/// `m` the model lacks are added (as discrete entities). Node i gets tag i + 1.
ModelTags write_model(const Mesh& m);

}  // namespace homesh::gmsh_adapter
