#pragma once
// Putting the nodes a volume mesh's order raising added on its CAD curves and
// surfaces (issue 24; the first step of curving/curve_volume.h).
#include <Eigen/Core>

#include "core/volume_mesh.h"
#include "curving/curve_volume.h"

namespace homesh {

struct VolumePlacement {
  /// 3 by #nodes: how far each node moved (zero where it did not).
  Eigen::Matrix3Xd displacement;
  /// Nodes placed: at their element's interpolated parameters, or, where those
  /// failed the check, at the closest point to where they were.
  int by_parameters = 0, by_projection = 0;
  double largest_move = 0;
};

/// Puts every node of m that is not a corner of its lines, triangles or
/// tetrahedra and lies on a CAD curve or surface (node_class dim 1 or 2 with
/// geometry) on it, as Gmsh's setOrder does: at the CAD's point for the
/// parameters interpolated, at the node's place in its line or triangle, from
/// the element's corners' parameters on that curve or surface (theirs if they
/// lie on it, else found by cad.parameters). Where the point lands more than
/// half the element's longest edge from the straight node (across a periodic
/// seam, at a degenerate point, from corners whose parameters the CAD could not
/// give), or a node is in no line or triangle, the closest point to the
/// straight node (cad.closest) is taken instead. Sets the placed nodes'
/// parameters. Throws homesh::Error if a closest point is not finite.
VolumePlacement place_on_volume_cad(VolumeMesh& m, const VolumeCad& cad);

}  // namespace homesh
