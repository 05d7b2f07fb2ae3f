#pragma once
// The high-order mesh optimiser: moves the nodes of patches around the poor
// elements of a valid curved mesh to lower the thesis' distortion (Eq 3.48,
// curving/distortion_energy.h), keeping every element certified valid and
// never lowering a patch's worst certified minJ/maxJ.
//
// 1. Certified minJ/maxJ of every element (Bezier bounds, quality/jacobian_bounds.h).
//    Elements below `threshold` are poor.
// 2. Patches: the poor elements grown by `layers` rings of neighbours, split
//    into pieces that share no free node (curving/optimisation_patches.h;
//    Toulorge, Geuzaine, Remacle & Lambrechts, JCP 254, 2013, Sec 4).
// 3. On each patch, up to `newton_iterations` whole-patch Newton steps
//    (curving/patch_newton.h: every free node at once, a sparse damped Newton
//    system, each step backtracked until the energy drops and every moved
//    element is certified valid with minJ/maxJ at least the patch's worst at
//    the start), then up to `max_sweeps` node-by-node sweeps (0 by default;
//    Turner, Peiro & Moxey, "Curvilinear
//    mesh generation using a variational framework", CAD 103, 2018, Sec 4;
//    NekMesh's varopti): each free node takes a Newton step on the summed
//    energy of the elements around it, the 2 by 2 Hessian from differences of
//    the analytic gradient, its eigenvalues clamped positive (steepest descent
//    if none is), backtracked (Armijo) until the energy drops and the
//    elements around the node are certified valid with minJ/maxJ at least the
//    patch's worst at the start (a sum of distortions can trade its worst
//    element for the others; this floor forbids it step by step). Sweeps stop
//    when one lowers the patch energy by less than `tolerance` (relative) or
//    after `max_sweeps`.
// 4. The patch's elements are certified again: the patch is kept only if all
//    are valid and its worst minJ/maxJ did not drop; otherwise its nodes go
//    back where they were.
// Patches are independent and optimised in parallel (OpenMP).
//
// Mixed meshes: elements are the 2D elements of core/mesh.h (triangles, then
// quadrilaterals), patches grow through nodes shared by either kind, and a
// quadrilateral's energy is the same measure on the reference square, whose
// ideal element is the unit square (W = J; curving/distortion_energy.h), with
// its own tabulation (square Gauss rule plus the lattice of its det J's Bezier
// coefficients) and its certificate from the tensor-product Bezier bounds.
// Measured on issue 21's quad corpus (scripts/bench/quads_vs_gmsh.py, `curve`
// with the quadrilaterals' nodes free in this step, vertices free; machine
// loaded, times noisy), worst minJ/maxJ p = 2 / 3 / 4 from the linear mesh's:
// plate_holes_quads 0.198 -> 0.892 / 0.912 / 0.918 (1 / 6 / 30 s),
// circle_blq_1e-3_allquads 0.224 -> 0.852 / 0.908 / 0.920 (1.2 / 7 / 31 s),
// star1_blq_1e-3_allquads 0.212 -> 0.893 / 0.910 / 0.904 (1.7 / 14 / 71 s):
// every Gmsh method stays at the linear worst; mixed boundary layers
// naca0012_blq_1e-3_coarse 0.455 -> 0.906 / 0.886, naca23012_blq_1e-5 0.435
// -> 0.805 / 0.829 (p = 2 / 3, 0.5 / 1.8 s).
#include <vector>

#include "core/mesh.h"
#include "curving/curve_evaluator.h"
#include "curving/distortion_energy.h"
#include "quality/jacobian_bounds.h"
#include "quality/mesh_validity.h"

namespace homesh {

struct OptimiseOptions {
  /// Elements whose certified minJ/maxJ is below this are poor. 0.8: the worst
  /// value issue 16 asks of every curved boundary-layer mesh.
  double threshold = 0.8;
  /// Rings of neighbours added around the poor elements to make the patches.
  int layers = 3;
  /// 0 < first_layers < layers: the patches are first grown by first_layers rings only,
  /// and the elements still below the threshold after that are optimised again with
  /// patches of `layers` rings (Gmsh's HighOrderOptimize grows its patches likewise
  /// where they fall short: Toulorge et al., JCP 254, 2013, Sec 4). Small patches are
  /// cheap: the Newton systems of a p = 5 patch of 3 rings have 2-4k dofs, and their
  /// factorisations are most of the optimiser's time. 0: `layers` at once.
  int first_layers = 0;
  /// Most node-by-node sweeps per patch, after the Newton steps. 0: none (the Newton
  /// steps reach what 600 sweeps reach, at a tenth of the time: patch_newton.h).
  int max_sweeps = 0;
  /// A sweep lowering the patch energy by less than this fraction ends the patch.
  double tolerance = 1e-4;
  /// Most whole-patch Newton steps per patch (curving/patch_newton.h), before the
  /// sweeps; 0: sweeps only.
  int newton_iterations = 50;
  /// A Newton step lowering the patch energy by less than this fraction ends them.
  double newton_tolerance = 1e-2;
  /// When a patch's Newton steps end besides newton_tolerance: rest: once every element
  /// they move is certified at least the worst valid element outside every patch (or the
  /// threshold, if higher), where the mesh's worst then stays whatever further steps do;
  /// converged: only by newton_tolerance. Measured on issue 16's corpus
  /// (scripts/bench/README.md, "4 Dec 2026, late evening").
  enum class Until { rest, converged };
  Until until = Until::rest;
  /// false: the linear mesh's vertices (element corners) are held, as `curve`
  /// holds them by default (boundary-layer heights kept exactly); only the
  /// nodes the order raising added move. true: interior vertices move too.
  bool free_vertices = false;
  /// Which boundary nodes slide along their curve (with a CurveEvaluator):
  /// none; the nodes the order raising added (edge_nodes); those and the
  /// linear mesh's vertices on curves (all: a wall vertex may slide even where
  /// free_vertices holds the interior ones).
  enum class Slide { none, edge_nodes, all };
  Slide slide = Slide::all;
  /// Target of W = J * inv(J_target): the thesis' ideal equilateral element
  /// (ideal; the unit square for a quadrilateral) or each element's own straight-sided
  /// shape at the start (straight; for a quadrilateral the parallelogram of its
  /// bilinear shape's Jacobian at its centre).
  /// straight by default: against the ideal, a boundary-layer element of aspect
  /// ratio 1e4 has Theta_shape ~ 1e4, which the sweeps lower by bending it
  /// (minJ/maxJ 0.886 -> 1e-8 on the thin annulus of the tests, patch reverted).
  enum class Target { ideal, straight };
  Target target = Target::straight;
  /// r, alpha and the barrier floor epsilon of the energy.
  DistortionEnergyOptions energy;
  /// Gauss rule degree of the energy (per variable on quadrilaterals); 0: 2p.
  int quadrature_degree = 0;
  /// Share of the energy's weight on the nodes of the order 2(p - 1) lattice (2p - 1 on
  /// quadrilaterals; none for p = 1 triangles, whose det J is constant; corners
  /// and edges included, where the Gauss points never are), 0: the Gauss rule alone.
  /// Measured on issue 16's corpus (Newton steps, worst minJ/maxJ, 0 / 0.2):
  /// ellipse10_bl_1e-4 p = 5 0.81 / 0.91 (p = 3: 0.87 either way); the worst point of a
  /// p >= 4 element is often at a corner, which the Gauss points never see.
  double lattice_weight = 0.2;
  /// Bezier bounds behind every certificate.
  BoundsOptions bounds;
  /// Threads over the patches (0: one per core, whatever OpenMP's default is), where their
  /// work is worth it. The result does not depend on the count (patches share no free node).
  int threads = 0;
};

struct OptimiseResult {
  Mesh mesh;                ///< the optimised mesh (nodes moved, nothing else changed)
  double worst_before = 1;  ///< worst certified minJ/maxJ of the input
  double worst_after = 1;   ///< of the result
  int poor_before = 0;      ///< 2D elements below the threshold (valid ones)
  int poor_after = 0;
  int invalid = 0;           ///< elements of the input not certified valid (left alone)
  int patches = 0;           ///< patches optimised
  int accepted = 0;          ///< patches kept (the others were reverted or skipped)
  int sweeps = 0;            ///< node-by-node sweeps over all patches
  int newton_steps = 0;      ///< accepted whole-patch Newton steps over all patches
  int moved_nodes = 0;       ///< free nodes of the kept patches
  int sliding_nodes = 0;     ///< of which on a curve, sliding along it
  double energy_before = 0;  ///< summed energy of the kept patches, before and after
  double energy_after = 0;
  MeshValidity validity;  ///< the certified validity of `mesh` (by opt.bounds)
};

/// Optimises m (triangles and quadrilaterals of any order p >= 1, counter-clockwise
/// elements; at p = 1 only with free_vertices does a node move) with the nodes
/// where fixed[i] (#nodes) held, and the boundary nodes on curves that
/// `curves` slides (none if null) sliding as opt.slide says. Throws
/// homesh::Error on a wrong `fixed` size or bad options. `known`, if given, is
/// m's validity, reused where it fits (mesh_validity.h's overload: opt.bounds, m's
/// elements; an empty one is bounded afresh): a speed-up only.
OptimiseResult optimise_mesh(const Mesh& m, const std::vector<bool>& fixed,
                             const OptimiseOptions& opt = {},
                             const CurveEvaluator* curves = nullptr,
                             const MeshValidity* known = nullptr);

}  // namespace homesh
