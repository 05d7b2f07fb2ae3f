#pragma once
// Clearing the room before it opens: the free nodes of the existing mesh that
// lie where the layers will be are removed by collapsing each onto a front node
// next to it (edge collapse), so the elastic push (open_room.h) moves the front
// across empty room instead of squeezing those nodes into a thin band ahead of
// it. On a mesh much finer than the stack (a refined trailing edge, a fine
// mesh under a thick stack) the squeezed band is what stalls the push: its
// triangles flatten until a step of any size would fold one.
//
// The room of consecutive normal lines a, b (along a loop, fans included) is
// the quad (w_a, w_b, w_b + margin (t_b - w_b), w_a + margin (t_a - w_a)), w the
// wall node, t the front node's target. A free node v inside the room of the
// lines next to a front node f it shares an edge with is collapsed onto f: the
// two triangles of the edge f v go, v's other triangles take f for v. A
// collapse is done only if it keeps the mesh a manifold (f and v share exactly
// the two neighbours of that edge) and every triangle it changes
// counter-clockwise, not flat (radius ratio, Eq 4.17, at least min_quality: a
// sliver pointing along the front folds at the slightest push) and with front nodes of at most two
// consecutive lines (no triangle across the room, which would fold as the front moves); the nodes
// nearest the wall go first, sweeping until none collapses. Removed nodes stay in m.x, used by no
// triangle.
#include <Eigen/Core>
#include <vector>

#include "core/mesh.h"

namespace homesh {

/// The room as above: `lines` are the normal lines in order along the walls,
/// wall[k] and front[k] the wall node and front node of line k, target.col(k)
/// where the front node goes, next[k] the following line (-1 at the end of an
/// open wall).
struct Room {
  std::vector<int> wall, front, next;
  Eigen::Matrix2Xd target;
};

/// Collapses, in place, the nodes of the linear, counter-clockwise mesh m with
/// free[i] (#nodes) that lie in the room (margin >= 1 scales its depth) onto
/// front nodes (or, failing that, onto another neighbour, those beyond the
/// room first) as above. Triangles keep their order and surfaces, the removed
/// ones dropped. Returns the removed nodes.
std::vector<int> clear_room(Mesh& m, const Room& room, const std::vector<bool>& free,
                            double margin = 1.2, double min_quality = 0.02);

/// Removes the nodes of m no triangle, line or point uses, moving the last
/// nodes into the holes so that the nodes before the first hole and those not
/// moved keep their index. Returns #old nodes new indices (-1 for a removed one).
std::vector<int> drop_unused_nodes(Mesh& m);

}  // namespace homesh
