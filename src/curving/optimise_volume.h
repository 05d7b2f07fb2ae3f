#pragma once
// The high-order optimiser for tetrahedra (issue 24): patches round the
// elements below a certified minJ/maxJ threshold, their nodes moved to lower
// an untangling shape energy, nodes on CAD surfaces and curves sliding on them;
// a patch's result is kept only if certified no worse. The 3D counterpart of
// curving/optimise_mesh.h, for the elements the elastic analogy cannot mend
// (a tetrahedron with all four corners on a curved wall has no node inside).
#include <vector>

#include "core/volume_mesh.h"
#include "curving/curve_volume.h"
#include "quality/mesh_validity.h"

namespace homesh {

struct VolumeOptimiseOptions {
  /// Elements of certified minJ/maxJ below this are optimised.
  double threshold = 0.5;
  /// A patch is its poor elements grown by this many layers (through shared corners).
  int rings = 1;
  /// L-BFGS iterations per round, and barrier rounds per patch: rounds go on
  /// while the patch's lowest det J / J0 rises by round_gain (relative, at
  /// least of 0.05). 20 rounds at 0.001 lift the corpus's coarse ellipsoid at
  /// p = 3 from 0.071 (6 rounds at 0.01) to 0.13, in 4.0 s instead of 1.6.
  int iterations = 60;
  int rounds = 20;
  double round_gain = 0.001;
  /// Move the corners (vertices) of the linear mesh inside the volume too.
  bool move_vertices = true;
  /// Slide the linear mesh's vertices on CAD surfaces and curves too (else they
  /// stay where the mesher put them).
  bool slide_vertices = false;
  /// If not empty (#tetrahedra flags): only the flagged elements below the
  /// threshold seed patches (the children of a split, not the elements earlier
  /// starts could not lift).
  std::vector<char> only;
};

struct VolumeOptimiseResult {
  int patches = 0;
  int accepted = 0;
  /// Worst certified minJ/maxJ of the mesh before and after.
  double before = 0, after = 0;
};

/// Optimises m round its elements below o.threshold; `validity` (m's, as
/// volume_validity gives it) is updated to the result's. Nodes on curves and
/// surfaces with CAD geometry stay on it (cad.closest after each step); nodes
/// on model points, on discrete entities, and the corners of the linear mesh on
/// the boundary stay where they are.
///
/// Energy of a patch, after Toulorge, Geuzaine, Remacle & Lambrechts (2013,
/// "Robust untangling of curvilinear meshes"): over its elements and the points
/// q of the lattice of det J's degree 3(p-1) (corners, edges and faces
/// included, where a curved element's det J is least), the mean of
///   (j_q - 1)^2 + log((j_q - b) / (1 - b))^2,   j_q = det J_q / J0_e,
/// J0_e the element's straight-sided det J at the start. The first term evens
/// det J out (minJ/maxJ, the measure homesh certifies); the second is a barrier
/// at b, set each round just below the patch's lowest j_q, so a round never
/// lowers it and lifting it pays; rounds while it rises. Finite from a tangled
/// start (b below the most negative j_q), so one energy untangles and improves.
/// Minimised by L-BFGS with a backtracking line search (Nocedal & Wright 2006,
/// Alg 7.5), nodes on CAD projected back after each trial step and kept within
/// a quarter of their distance to their elements' nearest other node (so never
/// across a face's trimmed edge).
VolumeOptimiseResult optimise_volume(VolumeMesh& m, const VolumeCad& cad, MeshValidity& validity,
                                     const VolumeOptimiseOptions& o = {});

}  // namespace homesh
