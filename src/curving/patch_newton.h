#pragma once
// Whole-patch Newton steps of the high-order optimiser (curving/optimise_mesh.h):
// every free node of a patch moves at once, along the solution of
//
//   (H + lambda diag(H)) d = -g,
//
// g and H the gradient and Hessian of the patch's summed distortion energy
// (curving/distortion_energy.h) by the free nodes' coordinates (a sliding
// node's by its curve parameter u: x = C(u), g_u = g . C'(u), H_uu = C'^T H C',
// the curvature term dropped), H assembled from the elements' exact Hessians
// (distortion_energy_hessian; forward differences of the
// gradient, 2 n gradients per element, took the optimiser 0.35 s instead of
// 0.16 s on circle_nolayer_coarse at p = 5, same result) (a quadrilateral's projected
// onto the positive semi-definite matrices, its negative eigenvalues set to 0:
// on the all-quad cases of issue 21 with free vertices, whole-mesh patches whose
// Hessian is indefinite kept lambda at 0.1-1 and used all 50 steps; projected,
// p = 3 worst minJ/maxJ plate_holes_quads 0.892 -> 0.912 in 4 s instead of 9,
// star1_blq_1e-3_allquads 0.876 -> 0.909 in 12 s instead of 18; triangles'
// are kept as they are), lambda a Levenberg-Marquardt
// damping raised until the sparse LDL^T factorisation (fem/amd_ldlt.h, the Hessian's
// pattern fixed per patch and analysed once) is positive definite and
// the step is accepted, lowered after each accepted step (Toulorge, Geuzaine,
// Remacle & Lambrechts, JCP 254, 2013, Sec 3.4: Newton on the whole patch;
// Gmsh's HighOrderOptimize). A step is backtracked (Armijo) until the energy
// drops and every element with a moved node is certified valid (Bezier bounds)
// with minJ/maxJ at least `floor`.
//
// Why not only node-by-node sweeps: in a boundary layer of aspect ratio 100+,
// the bulge of a curved wall edge must be spread through many element layers
// at once; a node moving within its own star sees the layer above and below
// held, and the sweeps need hundreds of passes (ellipse10_bl_1e-4 p = 3:
// worst minJ/maxJ 0.70 after 3 x 60 sweeps, 0.82 after 600, 16 s).
#include <Eigen/Core>
#include <limits>
#include <vector>

#include "core/mesh.h"
#include "curving/curve_evaluator.h"
#include "curving/distortion_energy.h"
#include "fem/element_tabulation.h"
#include "quality/jacobian_bounds.h"

namespace homesh {

/// Nodes sliding along curves. The arrays are per sliding node (a p = 5 mesh's boundary
/// is a few percent of its nodes), `slot` per node: its place in them, -1 if it does not
/// slide. u: the parameter (kept unwrapped on closed curves while optimising); range:
/// that of the node's curve.
struct SlidingNodes {
  const CurveEvaluator* curves = nullptr;
  std::vector<int> slot;  ///< per node
  std::vector<int> tags;
  std::vector<double> params;
  std::vector<CurveRange> ranges;

  /// n nodes, none sliding.
  void reset(int n) {
    slot.assign(n, -1);
    tags.clear();
    params.clear();
    ranges.clear();
  }
  /// Node i slides along curve `tag` (range r) from parameter u.
  void add(int i, int tag, double u, const CurveRange& r) {
    slot[i] = static_cast<int>(tags.size());
    tags.push_back(tag);
    params.push_back(u);
    ranges.push_back(r);
  }
  bool slides(int i) const { return slot[i] >= 0; }
  int tag(int i) const { return tags[slot[i]]; }
  double& u(int i) { return params[slot[i]]; }
  double u(int i) const { return params[slot[i]]; }
  const CurveRange& range(int i) const { return ranges[slot[i]]; }
  /// C(u) of node i's curve (u wrapped into the range on a closed curve).
  Eigen::Vector2d point(int i, double u, Eigen::Vector2d* tangent = nullptr) const {
    return curves->point(tag(i), wrap_parameter(range(i), u), tangent);
  }
};

/// Certified bounds of det J of 2D element e of m (triangle, or quadrilateral
/// beyond the triangles) with nodes X.
JacobianBounds element_jacobian_bounds(const Mesh& m, int e, const Eigen::Matrix2Xd& X,
                                       const BoundsOptions& opt);

/// One patch: its 2D elements (triangles, then quadrilaterals: core/mesh.h),
/// its free nodes (ascending), each element's target inverse T
/// (distortion_energy.h), and what the steps keep.
struct PatchProblem {
  const Mesh* mesh = nullptr;
  const std::vector<int>* elements = nullptr;
  const std::vector<int>* free_nodes = nullptr;
  const std::vector<Eigen::Matrix2d>* targets = nullptr;
  const ElementTabulation* tab = nullptr;       ///< of the triangles
  const ElementTabulation* quad_tab = nullptr;  ///< of the quadrilaterals (if any)
  DistortionEnergyOptions energy;
  BoundsOptions bounds;
  /// No accepted step takes an element below this certified minJ/maxJ.
  double floor = 0;
  /// The steps end once every element with a free node is certified at least this (the
  /// worst of the mesh outside the patches: steps beyond it cannot raise the mesh's
  /// worst); +infinity: never.
  double enough = std::numeric_limits<double>::infinity();
};

struct PatchNewtonResult {
  int iterations = 0;  ///< accepted steps
  double energy_before = 0, energy_after = 0;
};

/// At most max_iterations accepted steps on the nodes x (all of the mesh's; only
/// the patch's free nodes change, sliding nodes' u in `sliding` with them);
/// stops when a step lowers the energy by less than `tolerance` (relative), when every
/// element with a free node reaches problem.enough, or when no damping gives an
/// acceptable step. Safe to run on patches sharing no free
/// node in parallel.
PatchNewtonResult patch_newton(const PatchProblem& problem, Eigen::Matrix2Xd& x,
                               SlidingNodes& sliding, int max_iterations, double tolerance);

}  // namespace homesh
