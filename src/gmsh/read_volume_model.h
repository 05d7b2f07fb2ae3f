#pragma once
// Gmsh model -> core volume mesh (issue 24).
#include <string>
#include <vector>

#include "core/volume_mesh.h"

namespace homesh::gmsh_adapter {

/// True if the current model has a 3D mesh (any element of dimension 3).
bool model_has_volume_mesh();

/// Reads the mesh of the current Gmsh model: entities of dimension 0..3 with
/// their boundaries, physical groups, nodes with their classification and
/// parameters, point, line, triangle and tetrahedron elements, grouped by
/// entity (core/volume_mesh.h). Node i of the result is the i-th node in
/// increasing Gmsh tag order. Throws homesh::Error naming `source` if the
/// model holds no tetrahedra, other 3D or 2D elements (hexahedra, prisms,
/// pyramids, quadrilaterals, naming the type), incomplete ones, elements of
/// mixed orders or of an order above kMaxTetrahedronOrder, non-finite
/// coordinates, or elements that repeat a corner. `element_tags`, if given,
/// receives the Gmsh element tag of each tetrahedron of the result.
VolumeMesh read_volume_model(const std::string& source,
                             std::vector<std::size_t>* element_tags = nullptr);

}  // namespace homesh::gmsh_adapter
