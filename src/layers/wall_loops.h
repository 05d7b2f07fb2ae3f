#pragma once
// The walls a boundary layer grows from (thesis Section 4.3): the boundary lines
// of chosen curves, chained into closed loops or open chains, oriented with the
// domain on their left. An open wall (the floor of a channel, a ramp) ends at
// both ends on another, non-wall boundary line, along which its layers end.
#include <array>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/wall_curves.h"

namespace homesh {

/// One wall of a linear mesh (corners of higher-order lines): a closed loop or
/// an open chain.
struct WallLoop {
  /// #wall nodes node indices in order along the wall: the domain lies on the
  /// left of each edge nodes[i] -> next(i), so an outer boundary runs
  /// counter-clockwise and a hole clockwise. A closed loop has as many wall
  /// edges as nodes, an open chain one fewer.
  std::vector<int> nodes;
  /// #wall nodes the triangle on the left of edge nodes[i] -> next(i), the only
  /// one it bounds (for the last node of an open chain: of its adjacent line).
  std::vector<int> triangles;
  /// #wall nodes the curve tag of edge nodes[i] -> next(i) (as above).
  std::vector<int> curves;
  bool closed = true;
  /// Open chains: the other nodes of the non-wall boundary lines at the ends,
  /// ends[0] -> nodes.front() and nodes.back() -> ends[1], and those lines'
  /// indices in the mesh; -1 for closed loops.
  std::array<int, 2> ends{-1, -1};
  std::array<int, 2> end_lines{-1, -1};

  int size() const { return static_cast<int>(nodes.size()); }
  int edges() const { return closed ? size() : size() - 1; }
  /// The boundary node before nodes[i] (cyclically, or ends[0]).
  int prev(int i) const { return i > 0 ? nodes[i - 1] : closed ? nodes.back() : ends[0]; }
  /// The boundary node after nodes[i] (cyclically, or ends[1]).
  int next(int i) const { return i + 1 < size() ? nodes[i + 1] : closed ? nodes.front() : ends[1]; }
};

/// The boundary lines of m on `curves`, chained into closed loops and open
/// chains (open chains first). Triangles must be counter-clockwise (valid).
/// Throws homesh::Error, naming the place, if no line lies on the curves, a
/// wall line bounds no triangle or two (an interface, not a wall), a wall node
/// has more than two wall edges, an open chain does not end on exactly one
/// other boundary line, or one such line ends two chains.
std::vector<WallLoop> wall_loops(const Mesh& m, const std::vector<int>& curves);

}  // namespace homesh
