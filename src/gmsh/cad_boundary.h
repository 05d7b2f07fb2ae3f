#pragma once
// High-order boundary nodes placed on the CAD curves of the current Gmsh model.
#include <Eigen/Core>

#include "core/mesh.h"

namespace homesh::gmsh_adapter {

/// Number of chords used to tabulate arc length along a boundary edge.
constexpr int kArcLengthChords = 64;

/// Positions of all nodes of `m` with the interior nodes of every boundary line
/// that lies on a CAD curve moved onto that curve (curvilinear placement, not
/// chordal projection): between the parameters of the line's end nodes, at the
/// arc-length fractions of the reference line nodes (equally spaced), arc length
/// tabulated with kArcLengthChords chords. Closed curves are handled across
/// their seam. Other nodes keep their position. Updates node_class[i].u of the
/// nodes of those lines. Returns 2 by #nodes positions.
Eigen::Matrix2Xd place_on_cad(Mesh& m);

}  // namespace homesh::gmsh_adapter
