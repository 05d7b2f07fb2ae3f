#pragma once
// Curving a linear (or any-order) mesh to order p: the order is raised with
// straight sides (core/raise_order.h), the boundary nodes go to the targets
// `place` gives (on the CAD, or on curves rebuilt from the boundary:
// boundary_reconstruction.h), and the interior follows the augmented elastic
// analogy (deform_mesh.h) with every element certified valid. With
// fixed_vertices the linear mesh's interior vertices are held where they are
// (boundary-layer heights kept exactly) and only the nodes the order raising
// added move; if that solve, or one restricted by deform.layers or
// deform.reach, cannot reach the whole motion, the whole mesh is solved again
// with every interior node free (the thesis' setting).
#include <Eigen/Core>
#include <functional>

#include "core/mesh.h"
#include "curving/boundary_reconstruction.h"
#include "curving/deform_mesh.h"

namespace homesh {

struct CurveOptions {
  int order = 2;               ///< p, 2 to kMaxOrder
  bool fixed_vertices = true;  ///< hold the linear mesh's interior vertices (see above)
  DeformOptions deform;        ///< the analogy; its defaults are the curve stage's
  /// Without CAD: how the boundary curves are rebuilt (used by the caller's `place`).
  BoundaryReconstructionOptions boundary;
};

struct CurveResult {
  DeformResult deform;            ///< of the last solve
  bool fell_back = false;         ///< the restricted solve fell short: the whole mesh was solved
  double restricted_reached = 0;  ///< the restricted solve's reached fraction, if it fell back
};

/// m at order opt.order with its boundary nodes at place(raised) (2 by nodes
/// of the raised mesh; only the columns of boundary_nodes(raised) are read;
/// `place` may update the raised mesh's node classification, e.g. curve parameters)
/// and its interior by the analogy. result.deform.complete says whether the
/// whole motion was reached with every element valid. Throws as deform_mesh.
CurveResult curve_mesh(const Mesh& m, const std::function<Eigen::Matrix2Xd(Mesh& raised)>& place,
                       const CurveOptions& opt = {});

}  // namespace homesh
