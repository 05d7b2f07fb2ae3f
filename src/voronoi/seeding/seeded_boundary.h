#pragma once
// The boundary a Voronoi mesh is grown in: plane surfaces with their loops of
// curves, the curves finely sampled, and the boundary seeds on them (made
// from the CAD by gmsh/boundary_sampling.h).
#include <Eigen/Core>
#include <map>
#include <vector>

#include "core/mesh.h"

namespace homesh {

/// A curve as a boundary loop runs along it: backwards if `reversed`.
struct LoopCurve {
  int tag = -1;
  bool reversed = false;
};

/// A surface and its boundary loops, each a closed chain of curves in
/// Gmsh's orientation (the surface on the left if its normal is +z).
struct SurfaceBoundary {
  int tag = -1;
  std::vector<std::vector<LoopCurve>> loops;
};

/// The surfaces' boundary curves, sampled finely and seeded.
struct SeededBoundary {
  std::vector<SurfaceBoundary> surfaces;
  /// Boundary seeds (2 by B) and where each lies: on a model point (dim 0)
  /// or inside a curve (dim 1, with its parameter u).
  Eigen::Matrix2Xd seeds;
  std::vector<NodeClass> classes;
  /// Per curve, its seeds from its start to its end, ends included (a closed
  /// curve's point at both ends).
  std::map<int, std::vector<int>> curve_seeds;
  /// Per curve, `samples` + 1 points from start to end, uniform in u.
  std::map<int, Eigen::Matrix2Xd> curve_samples;
};

}  // namespace homesh
