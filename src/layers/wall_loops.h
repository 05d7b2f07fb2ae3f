#pragma once
// The walls a boundary layer grows from (thesis Section 4.3): the boundary lines
// of chosen curves, chained into closed loops oriented with the domain on
// their left.
#include <string>
#include <vector>

#include "core/mesh.h"

namespace homesh {

/// One closed wall loop of a linear mesh (corners of higher-order lines).
struct WallLoop {
  /// #wall nodes node indices in order around the loop: the domain lies on the
  /// left of each edge nodes[i] -> nodes[i + 1] (cyclically), so an outer
  /// boundary runs counter-clockwise and a hole clockwise.
  std::vector<int> nodes;
  /// #wall nodes the triangle on the left of edge i, the only one it bounds.
  std::vector<int> triangles;
  /// #wall nodes the curve tag of edge i.
  std::vector<int> curves;
};

/// Curve tags of the walls named in `walls`: each entry is the name of a
/// physical group of dimension 1 (all its curves) or a curve tag. Throws
/// homesh::Error naming an entry that is neither, with the known curve groups.
std::vector<int> wall_curves(const Mesh& m, const std::vector<std::string>& walls);

/// The boundary lines of m on `curves`, chained into closed loops. Triangles
/// must be counter-clockwise (valid). Throws homesh::Error, naming the place,
/// if no line lies on the curves, a wall line bounds no triangle or two (an
/// interface, not a wall), a wall node has more than two wall edges, or a chain
/// of wall lines ends without closing (open walls are not supported).
std::vector<WallLoop> wall_loops(const Mesh& m, const std::vector<int>& curves);

}  // namespace homesh
