#pragma once
// The current Gmsh model's CAD as the 3D curving needs it (curving/curve_volume.h).
#include "curving/curve_volume.h"

namespace homesh::gmsh_adapter {

/// Closest points on the model's curves and surfaces by Gmsh's getClosestPoint
/// (OpenCASCADE's projection for OCC models: seams and degenerate points of
/// periodic surfaces are its business, and a node projected from the straight
/// element is never sent across a seam as interpolated parameters would be).
/// Discrete entities have no geometry. Gmsh's errors become homesh::Error.
VolumeCad volume_cad();

}  // namespace homesh::gmsh_adapter
