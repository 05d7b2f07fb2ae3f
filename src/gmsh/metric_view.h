#pragma once
// A metric field read from a Gmsh post-processing view holding a tensor field
// (Gmsh's convention for anisotropic background meshes, the one of
// voronoi/metric/metric_field.h: |v|_M = sqrt(v^T M v), eigenvalues 1/h^2).
#include <string>

#include "voronoi/grid/cartesian_grid.h"
#include "voronoi/metric/metric_field.h"

namespace homesh::gmsh_adapter {

/// Whether `spec` names a view: "viewN" (the view of tag N already loaded,
/// e.g. merged by the input .geo; N digits) or a file name ending in .pos or
/// .msh.
bool names_metric_view(const std::string& spec);

/// The tag of the view `spec` names (names_metric_view): N for "viewN",
/// else the last view of the file, merged into the current Gmsh session.
/// Throws homesh::Error naming `spec` if there is no such view or file.
int metric_view_tag(const std::string& spec);

/// The tensor view `tag` probed at the nodes of `coarse` (its first step;
/// M = [T_xx, (T_xy + T_yx) / 2; (T_xy + T_yx) / 2, T_yy] of the 9
/// components T_xx, T_xy, T_xz, T_yx, ...). A node outside the view's
/// elements takes the tensor of the nearest node inside (grid steps).
/// Throws homesh::Error if the view holds no tensors, covers no node, or a
/// tensor is not symmetric positive definite.
MetricField metric_from_view(int tag, const CartesianGrid& coarse);

}  // namespace homesh::gmsh_adapter
