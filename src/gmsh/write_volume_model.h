#pragma once
// Core volume mesh -> Gmsh model (issue 24).
#include "core/volume_mesh.h"
#include "gmsh/write_model.h"

namespace homesh::gmsh_adapter {

/// Replaces the mesh of the current Gmsh model with `m`, as write_model does for
/// planar meshes: entities and physical groups the model lacks are added (as
/// discrete entities), node i gets tag i + 1 (with its parameters on its curve or
/// surface where every node of that entity has them), elements get the tags of
/// VolumeMesh::tetrahedron_tag. Throws homesh::Error if m's elements are not
/// grouped by entity (group_by_entity).
ModelTags write_volume_model(const VolumeMesh& m);

}  // namespace homesh::gmsh_adapter
