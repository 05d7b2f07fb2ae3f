#pragma once
// Detaching the existing mesh from its walls (thesis Section 4.3): before the
// elastic analogy pushes the boundary into the domain, every wall node gets a
// front node for each of its normals, and the existing triangles are re-attached
// to the front nodes, so the walls (nodes, lines, classification) stay put and
// the room opened between wall and front is later filled with layers. At the
// ends of an open wall the triangles fan from the wall edge to the adjacent
// boundary edge, and the front node takes them all.
//
// At a single-normal node the front node starts at the wall node and takes all
// its triangles. At a fan of m normals (Fig 4.7) the triangles around the wall
// node, ordered counter-clockwise from the outgoing wall edge, are shared out
// among the m front nodes in m contiguous groups, the split between normals j
// and j + 1 at the ring node nearest their mid-angle; a gap triangle
// (f_j, ring node, f_{j+1}) joins consecutive groups, so the front has no
// hanging node. Fan front nodes start a small distance eps along their normals
// (eps = 0.1 of the distance from the wall node to its nearest opposite edge,
// halved until every triangle is counter-clockwise).
#include <vector>

#include "core/mesh.h"
#include "layers/wall_loops.h"
#include "layers/wall_normals.h"

namespace homesh {

struct FrontSplit {
  /// m with wall corners replaced by front nodes (triangle e of m is triangle e
  /// here), the gap triangles appended, and the front nodes appended after m's
  /// nodes (classified on the surface of the wall edge's triangle). The wall
  /// nodes keep their place, classification and lines but no triangle uses them.
  Mesh mesh;
  /// front[l][i][j]: front node of direction j at node i of loop l.
  std::vector<std::vector<std::vector<int>>> front;
  int gap_triangles = 0;
};

/// Splits the linear, counter-clockwise mesh m at the loops' nodes with their
/// normals (normals[l][i] for node i of loop l). Throws homesh::Error if the
/// triangles around a wall node do not fan from one of its wall edges to the
/// other (another boundary touches the wall there), or a fan cannot be split
/// into valid triangles.
FrontSplit split_front(const Mesh& m, const std::vector<WallLoop>& loops,
                       const std::vector<std::vector<WallNormal>>& normals);

}  // namespace homesh
