#pragma once
// Curving a linear (or any-order) mesh to order p: the order is raised with
// straight sides (core/raise_order.h), the boundary nodes go to the targets
// `place` gives (on the CAD, or on curves rebuilt from the boundary:
// boundary_reconstruction.h), and then:
// 1. Placed: if the mesh with only the boundary nodes moved (the interior
//    straight, as Gmsh's setOrder leaves it) is certified valid with every
//    minJ/maxJ at least `accept_placed`, it is the result (no solve).
// 2. Elastic: the interior follows the augmented elastic analogy
//    (deform_mesh.h) with every element certified valid. With
//    fixed_vertices the linear mesh's interior vertices are held where they
//    are (boundary-layer heights kept exactly) and only the nodes the order
//    raising added move; if that solve, or one restricted by deform.layers or
//    deform.reach, cannot reach the whole motion, the whole mesh is solved
//    again with every interior node free (the thesis' setting). A valid guess
//    of step 1 that the solves do not beat (or that they break) is kept, or
//    optimised as a second start of step 3.
// 3. Optimised: if `optimise` and elements are left below
//    optimiser.threshold, the high-order optimiser (optimise_mesh.h) works on
//    patches round them, boundary nodes sliding along the curves `curves`
//    evaluates (held without one). If elements are still below the threshold
//    after a solve with the vertices held, the solve is done again with them
//    free, optimised likewise, and the better of the two results kept.
#include <Eigen/Core>
#include <functional>
#include <string>

#include "core/mesh.h"
#include "curving/boundary_reconstruction.h"
#include "curving/curve_evaluator.h"
#include "curving/curve_volume.h"
#include "curving/deform_mesh.h"
#include "curving/optimise_mesh.h"

namespace homesh {

struct CurveOptions {
  int order = 2;  ///< p, 2 to kMaxOrder (tetrahedra: kMaxTetrahedronOrder)
  /// Tetrahedral meshes (issue 24): curve_volume's options, its order taken from `order`.
  VolumeCurveOptions volume;
  bool fixed_vertices = true;  ///< hold the linear mesh's interior vertices (see above)
  DeformOptions deform;        ///< the analogy; its defaults are the curve stage's
  /// Without CAD: how the boundary curves are rebuilt (used by the caller's `place`).
  BoundaryReconstructionOptions boundary;
  /// Step 1's bar: the placed mesh is kept if its worst certified minJ/maxJ is at
  /// least this (> 1: never, always solve).
  double accept_placed = 0.9;
  /// Step 1 and the elements outside a local solve (placed_rings): the interior nodes of
  /// the elements with a moved boundary node blended from their edges
  /// (curving/interior_blending.h), not left straight.
  bool blend = true;
  /// Below this, a guess kept at `accept_placed` or better (any p), or the result of the
  /// local solve round a poorer guess, is solved again round its elements below this and
  /// `placed_rings` rings (placed_rings > 0), the result kept if better; no solve beyond
  /// (<= accept_placed: off). Where Gmsh's FastCurving beat a
  /// guess kept at 0.9 (star1_bl_1e-3 p = 3: 0.919 against 0.936) this lifts it (0.981 in
  /// 0.11 s, FastCurving's 0.25 s); the bar 0.98 for keeping a guess at all was slower.
  double polish = 0.98;
  /// ... only where at most this share of the elements is below `polish` (else no
  /// polish: the guess, or the local solve's result, stands). On circles6_bl_1e-3 at p = 5
  /// the guess is 0.965 with 62 % of the elements below 0.98: the polish solved 4541 of
  /// 7290 triangles in 2.0 s for 0.989 (Gmsh's FastCurving: 0.941 in 0.18 s). Chosen on
  /// issue 16's corpus, the 14 cases the polish touched (55 runs where Gmsh has a valid
  /// method; one fresh process a run), within Gmsh's fastest valid time: share 1 / 0.3 /
  /// 0.15 / 0.1 / 0.05: 27 / 35 / 38 / 42 / 46 runs; 0.05 left three runs below Gmsh's
  /// best (star1_bl_1e-3 p = 3: 0.919 against FastCurving's 0.936), 0.1 none; mean worst
  /// 0.9605 (share 1) against 0.9546 (0.1). `polish` 0.95 instead (share 1): 44 runs, but
  /// star2_bl_1e-4_fine p = 3 at 0.957 against Gmsh's 0.970.
  double polish_share = 0.1;
  /// Where more than polish_share of the elements are below `polish`: polish round the
  /// polish_share worst of them (true), or not at all (false). Off: on issue 16's corpus
  /// (one run side by side) it polished 10 runs more, for 0.001-0.016, at 1.5-5x their
  /// time (circles6_bl_1e-3 p = 4 0.028 -> 0.147 s), within Gmsh's fastest valid time 123
  /// against 127 of 146 runs; on the quad corpus it lifts star1_blq_1e-3 p = 3 from 0.926
  /// to 0.968, above FastCurving's 0.929 (scripts/bench/README.md).
  bool polish_worst = false;
  /// > 0: if the blended guess falls short, step 1 also tries moving the interior near
  /// the wall, each node with the nearest wall line's deviation, fading over this many
  /// line lengths (curving/wall_propagation.h), and keeps the better guess. On
  /// circle_bl_1e-5_fine at p = 4 (first cell 1e-5, thinner than the wall edges' bulge)
  /// the blended guess is invalid and the solve within reach took 7 s (12179 triangles);
  /// propagated it is 0.994 with no solve, 0.30 s (Gmsh's FastCurving: 0.50 in 0.34 s).
  /// On by default, chosen on issue 16's corpus with `polish` (scripts/bench/README.md).
  double propagate = 1;
  /// Placed below accept_placed (or invalid): the elastic solve is first posed only on
  /// the elements below it grown by this many rings (through shared nodes), its result kept
  /// if it reaches the whole motion with the worst at least `accept_local` (then optimised,
  /// step 3), else solved as usual (0: never). Measured on issue 16's corpus at p = 5, 1 /
  /// 2 rings / the solve within `reach`: circles6_nolayer 783 / 1156 / 1637 triangles
  /// solved, 0.25 / 0.72 / 1.1 s, worst 0.981 / 0.979 / 0.979; star4_nolayer_coarse 0.04 /
  /// 0.09 / 0.37 s, worst 0.920 / 0.913 / 0.913.
  /// 1 by default since the elements outside the region are blended (`blend`): with
  /// their interiors left straight it cost a downstream solver accuracy. DOLFINx's Poisson
  /// study on the plate (scripts/examples/dolfinx_poisson.py, p = 3, finest mesh): L2 error
  /// 5.3e-7, rate 4.22 after the solve within `reach`; 7.2e-7, 3.55 with 1 ring and
  /// straight interiors; 4.7e-7, 4.09 with 1 ring and blending (p = 2 unchanged, 4.1e-5);
  /// 5.2e-7, 4.04 with the polish too.
  int placed_rings = 1;
  /// ... from this order on. From p = 2 (it was 3): on issue 16's corpus at p = 2 (49
  /// cases, one fresh process each) the curving took 1.3 s in all against 4.2 s, within
  /// Gmsh's fastest valid time 24 of 34 runs against 23, within 2x 32 against 27, every
  /// target still met, the worst run 0.901 both (lshape_r05_bl_1e-3 0.030 -> 0.010 s,
  /// FastCurving 0.010 s; naca0024_bl_1e-3 0.910 -> 0.943). The thesis' rotation
  /// experiments start from the solve on the whole mesh (`rings=0`: the hole of
  /// tests/app/rotate_cli_test.cpp turns 166 deg from it, 157 from the local solve's).
  int placed_rings_from_order = 2;
  /// The local solve's result (`placed_rings`) is kept if certified valid with its worst
  /// at least this; the optimiser (step 3) then lifts its elements below the threshold.
  /// Below it, the solve within `reach` follows. It was accept_placed (0.9), which sent
  /// plate_holes_layers_1e-3 at p = 5 from a local solve of 342 triangles (0.878, 0.08 s)
  /// to one of 4055 (0.860, 0.6-2.2 s); optimised, 0.914 in 0.12 s against 0.951 in 0.66 s
  /// (Gmsh's FastCurving: 0.726 in 0.12 s). On issue 16's corpus (196 runs, one fresh
  /// process each, 141 where Gmsh has a valid method) 0 against 0.9: within Gmsh's fastest
  /// valid time 93 against 66 runs, within 2x 125 against 99, the whole corpus 69 s against
  /// 120 s; every target still met, worst 0.842 both, mean 0.9330 against 0.9364 (0.5: 93,
  /// 121, 102 s). The NACA-7526 case of tests/app/optimise_cli_test.cpp (15 layers, p = 3):
  /// the local solve 0.856, the solve within `reach` 0.992.
  double accept_local = 0;
  /// Step 3 on or off.
  bool optimise = true;
  /// Step 3's optimiser: OptimiseOptions' defaults (wall nodes sliding, whole-patch
  /// Newton steps, no node-by-node sweeps) but free interior vertices and the threshold
  /// 0.9 (the optimise stage's is 0.8). On issue 16's corpus (196 runs, p = 2-5) 0.9 meets
  /// the targets (0.9 where the wall turns < 30 degrees) in 196 runs, 0.8 in 190 (the six
  /// stopped at 0.85-0.90 unoptimised, e.g. plate_holes_bl_1e-4 p = 3: 0.849, 0.964 with
  /// 0.05 s of optimisation); total time 225 s against 217 s, worst 0.830 against 0.804.
  /// Measured on issue 16's corpus (scripts/bench/README.md), worst minJ/maxJ after
  /// curving, ellipse10_bl_1e-4 p = 2 / naca0012_bl_1e-3_coarse p = 4: solve alone 0.06 /
  /// 0.13; node-by-node sweeps with the wall held, 20 sweeps: 0.64 / - (vertices held),
  /// 0.66 / 0.54 (free); wall sliding 0.71 / 0.69; 60 sweeps 0.78 / 0.81 (200: 0.85 /
  /// 0.84 at 3x the time); whole-patch Newton steps 0.89 / 0.93 in a tenth of that time.
  /// Most passes of the optimiser from one solve: another pass (from where the last
  /// stopped) while elements stay below the threshold and the last pass lifted the worst
  /// by 0.02 or more.
  int optimise_passes = 3;
  /// Its patches first of one ring (first_layers = 1), grown to `layers` (3) only round
  /// the elements still below the threshold: on issue 16's corpus (196 runs, one run
  /// beside the 3-ring patches at once and first_layers = 2), total curving time 114.9 ->
  /// 101.1 s (2 rings: 109.8), within Gmsh's fastest valid time 53 -> 57 of 142 runs,
  /// within 2x 87 -> 95; every target still met, the worst run 0.835 -> 0.842, the mean
  /// 0.9427 -> 0.9367 (51 runs lower by > 0.005, at most circle_nolayer_coarse p = 5
  /// 0.977 -> 0.903, still above Gmsh's best 0.62; 11 higher).
  /// Where the linear wall is coarse for its curvature, its consecutive boundary lines
  /// turning by `coarse_turn` degrees or more somewhere it is smooth (curving/wall_turn.h),
  /// the optimiser's threshold is `coarse_threshold` if that is lower: the bar issue 16
  /// sets (0.9 where the wall turns by less than 30 degrees, 0.8 elsewhere). There the
  /// elements round the wall must bend most, and lifting the last of them from 0.8 to 0.9
  /// cost most of the curving: on issue 16's corpus (196 runs, 140 on such walls; one run
  /// beside the threshold 0.9 everywhere, its Gmsh times those of docs/bench) within Gmsh's
  /// fastest valid time 136 / 146 runs against 130, within 2x 146 against 144, the whole
  /// corpus 22.1 s against 42.1 s (flap_gap01_bl_1e-5 p = 5 3.57 -> 0.22 s, 0.893 -> 0.870;
  /// plate_holes_nolayer_coarse p = 5 0.935 -> 0.823 at half the time); every target still
  /// met, worst 0.802 against 0.842, mean 0.8925 against 0.9314 (coarse_threshold 0.85:
  /// 133, 145, 27.1 s, worst 0.834, mean 0.9128).
  double coarse_turn = 30;
  double coarse_threshold = 0.8;  ///< (>= optimiser.threshold: off)
  OptimiseOptions optimiser = [] {
    OptimiseOptions o;
    o.free_vertices = true;
    o.threshold = 0.9;
    o.first_layers = 1;
    return o;
  }();
};

struct CurveResult {
  Mesh mesh;               ///< the curved mesh (valid if deform.complete or placed)
  double worst_ratio = 1;  ///< its worst certified minJ/maxJ
  /// Its certified validity where curving had it at hand (by opt.optimiser.bounds, or the
  /// default bounds), else empty.
  MeshValidity validity;
  bool placed = false;             ///< step 1 sufficed: no solve, no optimisation
  bool polished = false;           ///< step 1's guess sufficed, then solved round its poorest
  double polish_bar = 0;           ///< ... round its elements below this
  std::string guess = "straight";  ///< step 1's guess kept: straight, blended or propagated
  double placed_worst = 0;         ///< step 1's worst certified minJ/maxJ (<= 0: invalid)
  DeformResult deform;             ///< of the last solve (if any; its mesh moved to `mesh`
                                   ///< where that is the result)
  /// The result comes from step 1's valid guess, not the solve: the solve fell short of it
  /// (incomplete, or poorer), and the guess was kept or optimised better than the solve.
  bool guess_over_solve = false;
  bool fell_back = false;         ///< the restricted solve fell short: solved with vertices free
  bool fell_back_whole = false;   ///< and that on the whole mesh (the region's fell short too)
  double restricted_reached = 0;  ///< the restricted solve's reached fraction, if it fell back
  bool freed_vertices = false;    ///< the result comes from step 3's solve with vertices free
  double wall_turn = 0;           ///< the linear wall's largest turn, degrees (curving/wall_turn.h)
  double threshold = 0;           ///< the optimiser's threshold used (see coarse_turn)
  bool optimised = false;         ///< step 3 ran
  OptimiseResult optimisation;    ///< its result (its mesh moved to `mesh`)
  double seconds = 0;             ///< wall time of the whole curving
  double place_seconds = 0;       ///< of which raising the order and placing the boundary
  double guess_seconds = 0;       ///< and step 1's guesses with their certification
  double elastic_seconds = 0;     ///< of which the elastic solves
  double optimise_seconds = 0;    ///< and the optimiser
};

/// m at order opt.order with its boundary nodes at place(raised) (2 by nodes
/// of the raised mesh; only the columns of boundary_nodes(raised) are read;
/// `place` may update the raised mesh's node classification, e.g. curve parameters)
/// and its interior as above. The result is valid if result.placed or
/// result.deform.complete (the elastic solve reached the whole motion with
/// every element valid). Throws as deform_mesh.
CurveResult curve_mesh(const Mesh& m, const std::function<Eigen::Matrix2Xd(Mesh& raised)>& place,
                       const CurveOptions& opt = {}, const CurveEvaluator* curves = nullptr);

}  // namespace homesh
