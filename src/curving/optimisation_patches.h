#pragma once
// The patches the high-order mesh optimiser (curving/optimise_mesh.h) works on:
// the poor elements grown by a few layers of neighbours, split into pieces
// that share no free node, so that each piece is optimised, certified and
// kept or reverted on its own (Toulorge, Geuzaine, Remacle & Lambrechts,
// "Robust untangling of curvilinear meshes", JCP 254, 2013, Sec 4: patches of
// n layers around each bad element, merged where they overlap). Elements are
// the 2D elements of core/mesh.h: triangles 0..T-1, then quadrilaterals
// T..T+Q-1 (as MeshValidity::ratio).
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "core/mesh.h"

namespace homesh {

/// Length scales of 2D element e with nodes at x: its straight (corner)
/// element's area divided by its longest corner-to-corner edge (a triangle's
/// smallest height; a rectangle's shorter side), and that longest edge.
std::pair<double, double> element_lengths(const Mesh& m, const Eigen::Matrix2Xd& x, int e);

struct OptimisationPatch {
  /// Ascending 2D element indices of the patch (triangles, then quadrilaterals).
  std::vector<int> elements;
  /// Ascending indices of the nodes that move: nodes of the patch not held
  /// and not on any element outside it (the patch's boundary stays).
  std::vector<int> free_nodes;
};

/// The patches of m around the 2D elements with poor[e] (#2D elements): those
/// elements, then `layers` >= 0 times every element sharing a node with the
/// set so far; the set is split into the connected pieces joined by free nodes
/// (held[i] marks the nodes that never move). Pieces with no free node are
/// dropped. Patches come in the order of their smallest element.
std::vector<OptimisationPatch> optimisation_patches(const Mesh& m, const std::vector<bool>& poor,
                                                    int layers, const std::vector<bool>& held);

}  // namespace homesh
