#pragma once
// Gmsh model -> core mesh.
#include <string>
#include <vector>

#include "core/mesh.h"

namespace homesh::gmsh_adapter {

/// Reads the mesh of the current Gmsh model: entities of dimension 0..2 with
/// their boundaries, physical groups, nodes with their classification, point,
/// line, triangle and quadrilateral elements. Node i of the result is the i-th
/// node in increasing Gmsh tag order. Throws homesh::Error naming `source` if
/// the model holds no triangles and no quadrilaterals, 3D elements, other 2D
/// elements or incomplete (serendipity) ones such as Gmsh's "Quadrilateral 8"
/// (naming the type), elements of mixed orders, nodes off the plane z = 0, or
/// elements check_mesh rejects. `element_tags`, if given, receives the Gmsh
/// element tag of each 2D element, triangles first, then quadrilaterals (the
/// numbering of core/mesh.h).
Mesh read_model(const std::string& source, std::vector<std::size_t>* element_tags = nullptr);

/// True if the current model has a 2D mesh (any element of dimension 2).
bool model_has_mesh();

/// True if some curve or surface of the current model is CAD (not discrete).
bool model_has_cad();

}  // namespace homesh::gmsh_adapter
