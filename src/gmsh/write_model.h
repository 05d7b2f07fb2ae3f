#pragma once
// Core mesh -> Gmsh model.
#include <cstddef>

#include "core/mesh.h"

namespace homesh::gmsh_adapter {

/// Element tags given to the mesh written into the model: point elements get
/// 1.., lines next, then triangles, quadrilaterals last; triangle e has tag
/// first_triangle + e, quadrilateral e first_quad + e = first_triangle +
/// num_triangles + e (2D element e of core/mesh.h has first_triangle + e).
struct ModelTags {
  std::size_t first_line = 1;
  std::size_t first_triangle = 1;
  std::size_t first_quad = 1;
};

/// Replaces the mesh of the current Gmsh model with `m`. Gmsh 4.8 has no bulk
/// setNodes, so the model's mesh is cleared and nodes/elements are re-added per
/// entity. Entities and physical groups already in the model are kept; those of
/// `m` the model lacks are added (as discrete entities). Node i gets tag i + 1.
ModelTags write_model(const Mesh& m);

}  // namespace homesh::gmsh_adapter
