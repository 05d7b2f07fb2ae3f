#pragma once
// Putting the nodes a volume mesh's order raising added on its CAD curves and
// surfaces (issue 24; the first step of curving/curve_volume.h).
#include <Eigen/Core>
#include <vector>

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

/// Gauss-Newton steps (four) on entity (dim, tag)'s parametrisation from
/// `params` (dim by n) towards those of the closest points to the columns of
/// x: what projection gives, by evaluations only (OCC's projection on a
/// B-spline surface costs 0.3 ms a point). Returns, per point, whether the
/// steps converged (the last one shorter than 1e-4 of its reach: the point is
/// on the CAD whatever the steps, only its place along it waits) to parameters
/// within the entity's range; near a degenerate point (a sphere's pole), across
/// a seam, or from parameters not finite they need not, and the caller projects.
std::vector<char> newton_closest(const VolumeCad& cad, int dim, int tag, const Eigen::Matrix3Xd& x,
                                 const std::vector<double>& reach, Eigen::MatrixXd& params);

}  // namespace homesh
