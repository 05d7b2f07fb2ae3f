#pragma once
// What a labelled grid says about its crystals: which pairs meet across a
// grid edge (the collisions of thesis Eq 2.10) and which reach the outside of
// the domain. Used by the fast-marching engine on its final labels.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "voronoi/engines/stencil_field.h"

namespace homesh {

struct LabelContacts {
  /// Pairs {a, b}, a < b, of labels on the two ends of a grid edge, sorted.
  std::vector<std::array<int, 2>> collisions;
  /// Labels 0..count-1 on a node with a grid neighbour outside the domain,
  /// sorted (none without a domain).
  std::vector<int> boundary_contacts;
};

/// labels: field.grid().node_count(), a crystal 0..count-1 or -1 (none).
LabelContacts label_contacts(const StencilField& field, const Eigen::VectorXi& labels, int count);

}  // namespace homesh
