#include "pipeline/stages/curve_stage.h"

#include <fmt/core.h>

#include <memory>

#include "core/error.h"
#include "curving/curve_mesh.h"
#include "gmsh/cad_boundary.h"
#include "gmsh/cad_curves.h"
#include "gmsh/gmsh_call.h"
#include "gmsh/volume_cad.h"
#include "pipeline/analogy_options.h"
#include "pipeline/optimiser_options.h"
#include "pipeline/quality_report.h"

namespace homesh {
namespace {

// Boundary targets on splines rebuilt from the linear boundary, said in the log,
// in the output's provenance (ctx.notes) and in ctx.results (boundary_rebuilt,
// corner_degrees, the chain counts).
Eigen::Matrix2Xd rebuilt_boundary(Context& ctx, const Mesh& raised,
                                  const BoundaryReconstructionOptions& b) {
  if (raised.num_lines() == 0)
    throw Error("stage 'curve': " + ctx.input +
                " has no CAD and no boundary lines to rebuild curves from");
  const BoundaryReconstruction r = reconstruct_boundary(raised, b);
  const std::string note = fmt::format(
      "curve: no CAD in {}: boundary rebuilt from the linear mesh (cubic spline, corners > {:g} "
      "deg kept sharp): {} closed loops, {} open chains, {} corners",
      ctx.input, b.corner_degrees, r.closed_loops, r.chains, r.corners);
  ctx.log.info("{}", note);
  ctx.notes.push_back(note);
  ctx.results["boundary_rebuilt"] = true;
  ctx.results["corner_degrees"] = b.corner_degrees;
  ctx.results["rebuilt_closed_loops"] = r.closed_loops;
  ctx.results["rebuilt_chains"] = r.chains;
  ctx.results["rebuilt_corners"] = r.corners;
  return r.target;
}

// The curve stage on a tetrahedral mesh (issue 24): curving/curve_volume.h.
void run_volume(Context& ctx, const CurveOptions& o) {
  if (!ctx.has_cad)
    throw Error("stage 'curve': " + ctx.input +
                " has tetrahedra but no CAD: homesh does not rebuild surfaces from a bare .msh "
                "yet (give the .geo, .step or .brep the mesh was made from)");
  VolumeCurveOptions v = o.volume;
  v.order = o.order;
  VolumeMesh& m = *ctx.volume;
  const VolumeCad cad = gmsh_adapter::volume_cad();
  const int input_tetrahedra = m.num_tetrahedra();
  const VolumeCurveResult r = curve_volume(m, cad, v);
  ctx.fields.clear();
  ctx.certify_volume(r.validity);  // the writers reuse it
  ctx.log.info(
      "curve: p = {}, {} tetrahedra: {} boundary nodes put on the CAD ({} by projection; "
      "largest move {:.3g}), "
      "elastic solve on {} tetrahedra ({} unknowns, {} CG iterations{}); {:.3f} s placing, "
      "{:.3f} s solving, {:.3f} s certifying",
      v.order, m.num_tetrahedra(), r.placed, r.projected, r.largest_move, r.region, r.unknowns,
      r.iterations, r.two_level ? ", two-level" : "", r.seconds_place, r.seconds_solve,
      r.seconds_certify);
  if (r.patches > 0)
    ctx.log.info("  optimiser: {} of {} patches kept, worst minJ/maxJ {:.4f} -> {:.4f} ({:.3f} s)",
                 r.optimised, r.patches, r.worst_before_optimiser, r.validity.worst,
                 r.seconds_optimise);
  if (r.split > 0)
    ctx.log.info(
        "  {} tetrahedra with four corners on the wall split (at an edge on the wall or their "
        "centroid): {} tetrahedra, {} before",
        r.split, m.num_tetrahedra(), input_tetrahedra);
  ctx.log.info("  {}", validity_line(m, r.validity));
  ctx.results = {{"patches", r.patches},
                 {"split", r.split},
                 {"optimised", r.optimised},
                 {"seconds_optimise", r.seconds_optimise},
                 {"worst", r.validity.worst},
                 {"invalid", r.validity.invalid},
                 {"placed", r.placed},
                 {"projected", r.projected},
                 {"region", r.region},
                 {"unknowns", r.unknowns},
                 {"iterations", r.iterations},
                 {"seconds_place", r.seconds_place},
                 {"seconds_solve", r.seconds_solve}};
}

void run(Context& ctx, const CurveOptions& o) {
  if (ctx.volume) return run_volume(ctx, o);
  Mesh& m = ctx.require_mesh("curve");
  std::unique_ptr<gmsh_adapter::CadCurves> cad;
  if (ctx.has_cad)
    gmsh_adapter::gmsh_call("stage 'curve': reading the CAD curves of " + ctx.input,
                            [&] { cad = std::make_unique<gmsh_adapter::CadCurves>(m); });
  CurveResult c = curve_mesh(
      m,
      [&](Mesh& raised) {
        if (!ctx.has_cad) return rebuilt_boundary(ctx, raised, o.boundary);
        Eigen::Matrix2Xd target;
        gmsh_adapter::gmsh_call("stage 'curve': placing nodes on the CAD of " + ctx.input,
                                [&] { target = gmsh_adapter::place_on_cad(raised); });
        return target;
      },
      o, cad.get());
  const DeformOptions& d = o.deform;
  if (c.fell_back) {
    const std::string restricted = std::string(o.fixed_vertices ? "vertices held, " : "") +
                                   (d.layers > 0 ? fmt::format("within {} element layers", d.layers)
                                    : d.reach > 0 ? fmt::format("within reach {:g}", d.reach)
                                                  : std::string("whole mesh"));
    ctx.log.info(
        "curve: the solve ({}) kept the mesh valid only up to {:.1f} % of the motion; "
        "solved again with every interior node free {}",
        restricted, 100 * c.restricted_reached,
        c.fell_back_whole ? "on the whole mesh" : "in the same region");
  }
  if (c.freed_vertices)
    ctx.log.info(
        "curve: optimised from the solve with the vertices held, elements stayed below {:g}; "
        "solved again with them free, optimised better from there",
        c.threshold);
  const DeformResult& r = c.deform;
  if (!c.placed && !r.complete)
    throw Error(fmt::format(
        "stage 'curve': the elastic analogy ({}) kept the mesh valid only up to {:.1f} % of "
        "the boundary motion ({} elements would become invalid); try more increments or "
        "another formulation",
        d.formulation, 100 * r.reached, r.invalid_at_failure));
  if (c.polished)
    ctx.log.info(
        "curve: order {}, boundary nodes placed, interior {}: {}; solved round its elements "
        "below {:g}{} ({} elements): worst minJ/maxJ {:.4f}, {:.2f} s",
        o.order, c.guess,
        c.placed_worst > 0 ? fmt::format("worst minJ/maxJ {:.4f}", c.placed_worst)
                           : std::string("not certified valid"),
        c.polish_bar,
        c.placed_worst < o.accept_placed ? fmt::format(" (first below {:g})", o.accept_placed)
                                         : std::string(),
        r.solved_triangles, r.worst_ratio, c.elastic_seconds);
  else if (!c.placed && o.accept_placed <= 1)
    ctx.log.info("curve: boundary nodes placed, interior {}: {}; solving", c.guess,
                 c.placed_worst > 0
                     ? fmt::format("worst minJ/maxJ {:.4f} < {:g}", c.placed_worst, o.accept_placed)
                     : std::string("not certified valid"));
  if (c.placed)
    ctx.log.info(
        "curve: order {}, boundary nodes placed, interior {}: worst minJ/maxJ {:.4f} >= {:g}, "
        "no solve",
        o.order, c.guess, c.worst_ratio, o.accept_placed);
  else if (!c.polished)
    ctx.log.info(
        "curve: order {}, formulation {}, nu {}, posed on {} of {} elements: {} solves, worst "
        "minJ/maxJ {:.4f}, {:.2f} s",
        o.order, d.formulation, d.params.poisson, r.solved_triangles, m.num_elements_2d(), r.solves,
        r.worst_ratio, c.elastic_seconds);
  if (c.guess_over_solve)
    ctx.log.info(
        "curve: the result comes from the {} guess (worst minJ/maxJ {:.4f}), which the solve "
        "fell short of",
        c.guess, c.placed_worst);
  if (c.optimised) {
    const OptimiseResult& op = c.optimisation;
    ctx.log.info(
        "curve: optimised {} patches round {} elements below {:g}{} ({} kept, {} nodes sliding "
        "on curves): worst minJ/maxJ {:.4f} -> {:.4f}, {:.2f} s",
        op.patches, op.poor_before, c.threshold,
        c.threshold < o.optimiser.threshold
            ? fmt::format(" (coarse_threshold: the wall's lines turn by up to {:.0f} degrees)",
                          c.wall_turn)
            : std::string(),
        op.accepted, op.sliding_nodes, op.worst_before, op.worst_after, c.optimise_seconds);
    ctx.results["optimised_patches"] = op.patches;
    ctx.results["optimised_accepted"] = op.accepted;
  }
  ctx.log.info("curve: worst minJ/maxJ {:.4f}, {:.2f} s", c.worst_ratio, c.seconds);
  ctx.results["worst"] = c.worst_ratio;
  ctx.results["placed"] = c.placed;
  ctx.results["polished"] = c.polished;
  ctx.results["guess_over_solve"] = c.guess_over_solve;
  ctx.results["optimised"] = c.optimised;
  ctx.results["wall_turn_degrees"] = c.wall_turn;
  ctx.results["threshold"] = c.threshold;
  ctx.results["seconds"] = c.seconds;
  ctx.results["place_seconds"] = c.place_seconds;
  ctx.results["guess_seconds"] = c.guess_seconds;
  ctx.results["elastic_seconds"] = c.elastic_seconds;
  ctx.results["optimise_seconds"] = c.optimise_seconds;
  m = std::move(c.mesh);
  if (c.validity.ratio.size() > 0) ctx.certify(std::move(c.validity));
  ctx.fields.clear();
}

}  // namespace

Stage curve_stage() {
  // Defaults: those of CurveOptions and DeformOptions (curving/deform_mesh.h says why).
  OptionTable<CurveOptions> t;
  t.add("p", &CurveOptions::order, integer(2, kMaxOrder),
        "element order, 2 to " + std::to_string(kMaxOrder));
  t.add(
      "increments", [](CurveOptions& o) -> int& { return o.deform.increments; }, integer(1, 1000),
      "load increments (halved where validity needs it); formulations whose terms depend on "
      "the deformation so far (force_q17, heat_*, metric_*, stiff_*) see only the straight "
      "mesh in one increment: give them 4 or more");
  t.add("vertices", &CurveOptions::fixed_vertices, choice<bool>({{"fixed", true}, {"free", false}}),
        "elastic solve: fixed: the linear mesh's vertices stay (boundary-layer heights kept "
        "exactly), only the nodes the order raising adds move; free: every interior node moves "
        "(the thesis); the optimiser moves interior vertices either way");
  t.add(
      "layers", [](CurveOptions& o) -> int& { return o.deform.layers; }, integer(0, 1000),
      "0: no effect; k > 0: solve only on the elements within k element layers of the "
      "moving boundary nodes, the rest held still (as Gmsh's Mesh.HighOrderNumLayers; "
      "replaces reach)");
  t.add(
      "reach", [](CurveOptions& o) -> double& { return o.deform.reach; }, real(0),
      "0: solve on the whole mesh; r > 0: only on the triangles within r times the size of "
      "the boundary triangles of the moving boundary, the rest held still (a boundary "
      "layer's thin elements do not shrink this region); the whole mesh if that fails");
  t.add("placed", &CurveOptions::accept_placed, real(0),
        "keep the mesh with the boundary nodes placed and the interior blended (or "
        "propagated), without a solve, if its worst minJ/maxJ is at least this (> 1: always "
        "solve)");
  t.add("polish", &CurveOptions::polish, real(0),
        "a first guess kept at `placed`, or the local solve's result (`rings`), if below "
        "this, is solved again round its elements below this, the result kept if better "
        "(<= placed: off)");
  t.add("blend", &CurveOptions::blend, boolean(),
        "place the interior nodes of the elements on the boundary by blending their curved "
        "edges in (0: leave them straight)");
  t.add("propagate", &CurveOptions::propagate, real(0),
        "> 0: the first guess moves the nodes near the wall with the nearest wall edge's "
        "bulge, fading over this many edge lengths (0: only the wall elements' interiors)");
  t.add("rings", &CurveOptions::placed_rings, integer(0, 1000),
        "p >= `rings_from`: if the placed mesh is poor, first solve only on its elements "
        "below `placed` grown by this many rings, kept as `local` says (0: never)");
  t.add("rings_from", &CurveOptions::placed_rings_from_order, integer(2, kMaxOrder),
        "the local solve (`rings`) from this order on");
  t.add("polish_share", &CurveOptions::polish_share, real(0, 1),
        "polish only where at most this share of the elements is below `polish`");
  t.add("polish_worst", &CurveOptions::polish_worst, boolean(),
        "where more than polish_share of the elements are below `polish`, polish round the "
        "polish_share worst of them (0: no polish there)");
  t.add("local", &CurveOptions::accept_local, real(0),
        "the local solve's result (`rings`) is kept, then optimised, if valid with its worst "
        "minJ/maxJ at least this; else the solve within `reach` follows");
  t.add("optimise", &CurveOptions::optimise, boolean(),
        "after the elastic solve, optimise the patches round elements below the threshold");
  t.add(
      "patch_rings", [](CurveOptions& o) -> int& { return o.optimiser.layers; }, integer(0, 100),
      "the optimiser's patches: its poor elements grown by this many rings of neighbours");
  add_optimiser_options(t, [](CurveOptions& o) -> OptimiseOptions& { return o.optimiser; });
  t.add("coarse_turn", &CurveOptions::coarse_turn, real(0, 180),
        "a wall whose linear lines turn by this many degrees or more where it is smooth "
        "(inside a curve, or where CAD curves join tangentially) is coarse for its curvature: "
        "there the optimiser's threshold is `coarse_threshold`");
  t.add("coarse_threshold", &CurveOptions::coarse_threshold, real(0, 1, "(]"),
        "the optimiser's threshold on a coarse wall (see coarse_turn), if lower than "
        "`threshold`");
  t.add(
      "corner", [](CurveOptions& o) -> double& { return o.boundary.corner_degrees; },
      real(0, 180, "()"),
      "without CAD (a .msh): boundary vertices turning more than this (degrees) stay sharp "
      "corners of the rebuilt spline curves");
  t.add(
      "tet_elastic", [](CurveOptions& o) -> bool& { return o.volume.elastic; }, boolean(),
      "tetrahedra: carry the boundary's displacement into the volume by the elastic analogy "
      "(0: move the boundary nodes only, as Gmsh's setOrder)");
  t.add(
      "tet_rings", [](CurveOptions& o) -> int& { return o.volume.rings; }, integer(0, 1000),
      "tetrahedra: the elastic solve takes the elements with a moved node and this many "
      "layers round them; the rest is held");
  t.add(
      "tet_two_level", [](CurveOptions& o) -> bool& { return o.volume.two_level; }, boolean(),
      "tetrahedra, p >= 4, tet_solver=cg: precondition CG by two levels, Jacobi and the "
      "analogy at order 2 solved exactly (the same mesh in a third of the iterations)");
  t.add(
      "tet_solve_order", [](CurveOptions& o) -> int& { return o.volume.solve_order; },
      integer(0, kMaxTetrahedronOrder),
      "tetrahedra: solve the elastic analogy at this order q (2 to p - 1) and interpolate it "
      "to order p: several times faster and smaller at p = 3-4, lower worst minJ/maxJ on most "
      "meshes (0: at p)");
  t.add(
      "tet_stiffening", [](CurveOptions& o) -> double& { return o.volume.stiffening; }, real(0, 4),
      "tetrahedra: Young's modulus of an element is its volume to this power, negated");
  t.add(
      "tet_optimise", [](CurveOptions& o) -> double& { return o.volume.optimise_threshold; },
      real(-1, 1),
      "tetrahedra: optimise round the elements left below this minJ/maxJ (<= 0: never)");
  t.add(
      "tet_patch_rings", [](CurveOptions& o) -> int& { return o.volume.optimise_rings; },
      integer(0, 100),
      "tetrahedra: the optimiser's patches are its poor elements and this many layers");
  t.add(
      "tet_split_caps", [](CurveOptions& o) -> bool& { return o.volume.split_wall_caps; },
      boolean(),
      "tetrahedra: split those with four corners on the wall that stay poor: at their edge "
      "lying on the wall before the optimiser, at that edge or their centroid if left invalid "
      "(kept only if certified better); 0: the tetrahedra stay the input's");
  t.add(
      "tet_solver", [](CurveOptions& o) -> std::string& { return o.volume.solver.method; },
      one_of(linear_solver_names()),
      "tetrahedra: the elastic solve's linear solver: " + names_text(linear_solver_names()) +
          " (cg: Jacobi-preconditioned, to 1e-6; petsc: the same through PETSc, shared among "
          "the processes of `mpirun -n N homesh ...`, PETSC_OPTIONS for others)");
  t.add(
      "tet_tolerance", [](CurveOptions& o) -> double& { return o.volume.solver.tolerance; },
      real(0, 1, "()"),
      "tetrahedra: the iterative solves (cg, petsc) stop at this relative residual");
  t.add(
      "tet_nu", [](CurveOptions& o) -> double& { return o.volume.nu; }, real(0, 0.5, "[)"),
      "tetrahedra: Poisson's ratio of the elastic analogy");
  add_analogy_options(
      t, [](CurveOptions& o) -> std::string& { return o.deform.formulation; },
      [](CurveOptions& o) -> FormulationParams& { return o.deform.params; },
      [](CurveOptions& o) -> LinearSolverOptions& { return o.deform.solver; });
  return make_stage<CurveOptions>(
      "curve",
      "order p with boundary nodes on the CAD (or on splines rebuilt from a bare .msh), "
      "interior blended from the curved edges if that is good enough, else by the elastic "
      "analogy (first round the poor elements only), then the "
      "optimiser round the elements left poor (wall nodes sliding on the CAD), valid",
      t, run, /*creates_mesh=*/false, /*handles_quads=*/true, /*handles_volumes=*/true);
}

}  // namespace homesh
