#pragma once
// The Gmsh element tags of the boundary lines read_model read, which it does
// not return (the triangles' come with read_model itself).
#include <cstddef>
#include <vector>

#include "core/mesh.h"

namespace homesh::gmsh_adapter {

/// #lines Gmsh element tags of the lines of `mesh`, which read_model read from
/// the current model, in the order of mesh.line (entity by entity, as
/// read_model takes them). Throws homesh::Error if the model's lines no
/// longer match the mesh's count.
std::vector<std::size_t> line_tags(const Mesh& mesh);

}  // namespace homesh::gmsh_adapter
