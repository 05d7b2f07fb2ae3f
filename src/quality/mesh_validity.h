#pragma once
// Certified validity of every triangle and quadrilateral of a mesh
// (quality/jacobian_bounds.h):
// an element counts as valid only if its Bezier bounds prove det J > 0 on the
// whole element; elements whose sign the subdivision could not decide count as
// invalid (never the reverse). It is mesh_quality (quality/mesh_quality.h) with
// no measures; call that to get measures in the same pass.
#include <Eigen/Core>

#include "core/mesh.h"
#include "quality/jacobian_bounds.h"

namespace homesh {

/// Name of the field of `ratio` (its Gmsh view, its meshio cell data): not
/// Gmsh's own "minJ/maxJ", the view of its AnalyseMeshQuality plugin.
constexpr const char* kValidityFieldName = "homesh: certified minJ/maxJ";

struct MeshValidity {
  /// #2D elements (triangles, then quadrilaterals: core/mesh.h) Gmsh's
  /// minJ/maxJ of each element (scaled_jacobian_ratio).
  Eigen::VectorXd ratio;
  /// #2D elements certified lower bound of det J of each element (on its
  /// reference element: the triangle (0,0), (1,0), (0,1) or the square [0, 1]^2).
  Eigen::VectorXd min_det;
  /// Elements not certified valid.
  int invalid = 0;
  /// #2D elements: whether its bounds were refined to the tolerance.
  std::vector<char> converged;
  /// Elements whose bounds reached max_subdivisions before the tolerance.
  int unconverged = 0;
  /// Smallest ratio and the 2D element holding it (-1 for an empty mesh).
  double worst = 1.0;
  int worst_element = -1;
  /// The options the bounds were refined by.
  double relative_tolerance = 0;
  int max_subdivisions = 0;
};

/// Sets v's invalid, unconverged, worst and worst_element from its per-element
/// min_det (valid: > 0, as JacobianBounds::valid_certified), converged and ratio.
void count_validity(MeshValidity& v);

/// Whether a mesh with `invalid` invalid elements and worst minJ/maxJ `worst` is
/// certified better than one with `than_invalid` and `than_worst`: fewer invalid
/// elements, or as many and a higher worst. The rule every curving stage keeps
/// or undoes a change by.
bool certified_better(int invalid, double worst, int than_invalid, double than_worst);

/// Bounds of det J of every triangle and quadrilateral of m.
MeshValidity mesh_validity(const Mesh& m, const BoundsOptions& opt = {});

/// mesh_validity(m, opt), given `known`, the validity of `before`: where `before`
/// has m's elements and `known` was refined by the same options, the elements
/// whose nodes are all where they are in `before` keep its bounds (the same
/// numbers: the bounds are a function of the nodes), and only the others are
/// bounded again. Otherwise every element is.
MeshValidity mesh_validity(const Mesh& m, const Mesh& before, const MeshValidity& known,
                           const BoundsOptions& opt = {});

/// A mesh and its certified validity, both optional (null: none known).
struct KnownValidity {
  const Mesh* mesh = nullptr;
  const MeshValidity* validity = nullptr;
};

/// The overload above with known's mesh and validity, or mesh_validity(m, opt)
/// if either is null.
MeshValidity mesh_validity(const Mesh& m, const KnownValidity& known,
                           const BoundsOptions& opt = {});

}  // namespace homesh
