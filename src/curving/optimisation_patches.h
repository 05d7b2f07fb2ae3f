#pragma once
// The patches the high-order mesh optimiser (curving/optimise_mesh.h) works on:
// the poor elements grown by a few layers of neighbours, split into pieces
// that share no free node, so that each piece is optimised, certified and
// kept or reverted on its own (Toulorge, Geuzaine, Remacle & Lambrechts,
// "Robust untangling of curvilinear meshes", JCP 254, 2013, Sec 4: patches of
// n layers around each bad element, merged where they overlap).
#include <vector>

#include "core/mesh.h"

namespace homesh {

struct OptimisationPatch {
  /// Ascending triangle indices of the patch.
  std::vector<int> elements;
  /// Ascending indices of the nodes that move: nodes of the patch not held
  /// and not on any triangle outside it (the patch's boundary stays).
  std::vector<int> free_nodes;
};

/// The patches of m around the triangles with poor[e]: those triangles, then
/// `layers` >= 0 times every triangle sharing a node with the set so far; the
/// set is split into the connected pieces joined by free nodes (held[i]
/// marks the nodes that never move). Pieces with no free node are dropped.
/// Patches come in the order of their smallest triangle.
std::vector<OptimisationPatch> optimisation_patches(const Mesh& m, const std::vector<bool>& poor,
                                                    int layers, const std::vector<bool>& held);

}  // namespace homesh
