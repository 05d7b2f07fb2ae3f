#include "pipeline/stages/curve_stage.h"

#include <fmt/core.h>

#include "core/error.h"
#include "core/raise_order.h"
#include "curving/boundary_reconstruction.h"
#include "curving/deform_mesh.h"
#include "pipeline/analogy_options.h"
#include "gmsh/cad_boundary.h"
#include "gmsh/gmsh_call.h"

namespace homesh {
namespace {

// Boundary targets on splines rebuilt from the linear boundary, said in the log,
// in the output's provenance (ctx.notes) and in ctx.results (boundary_rebuilt = 1, corner_degrees, the chain counts).
Eigen::Matrix2Xd rebuilt_boundary(Context& ctx, const Mesh& raised, double corner) {
  if (raised.num_lines() == 0)
    throw Error("stage 'curve': " + ctx.input +
                " has no CAD and no boundary lines to rebuild curves from");
  BoundaryReconstructionOptions b;
  b.corner_degrees = corner;
  const BoundaryReconstruction r = reconstruct_boundary(raised, b);
  const std::string note = fmt::format(
      "curve: no CAD in {}: boundary rebuilt from the linear mesh (cubic spline, corners > {:g} "
      "deg kept sharp): {} closed loops, {} open chains, {} corners",
      ctx.input, corner, r.closed_loops, r.chains, r.corners);
  ctx.log.info("{}", note);
  ctx.notes.push_back(note);
  ctx.results["boundary_rebuilt"] = 1;
  ctx.results["corner_degrees"] = corner;
  ctx.results["rebuilt_closed_loops"] = r.closed_loops;
  ctx.results["rebuilt_chains"] = r.chains;
  ctx.results["rebuilt_corners"] = r.corners;
  return r.target;
}

void run(Context& ctx, const Options& opt) {
  Mesh& m = ctx.require_mesh("curve");
  const int p = opt.get_int("p", 2, kMaxOrder);
  const double corner = opt.get_double("corner");
  if (!(corner > 0 && corner < 180))
    throw Error(fmt::format("stage 'curve': corner = {:g} must be in (0, 180) degrees", corner));
  const AnalogyChoice analogy = read_analogy_options(opt, "curve");
  DeformOptions d;
  d.formulation = analogy.formulation;
  d.params = analogy.params;
  d.solver = analogy.solver;
  d.increments = opt.get_int("increments", 1, 1000);
  const bool fixed_vertices = opt.get_choice("vertices", {"fixed", "free"}) == "fixed";
  d.layers = opt.get_int("layers", 0, 1000);
  d.reach = opt.get_double("reach");
  if (!(d.reach >= 0)) throw Error(fmt::format("stage 'curve': reach = {:g} must be >= 0", d.reach));
  if (d.layers > 0) d.reach = 0;

  Mesh raised = raise_order(m, p);
  Eigen::Matrix2Xd target;
  if (ctx.has_cad) {
    gmsh_adapter::gmsh_call("stage 'curve': placing nodes on the CAD of " + ctx.input,
                            [&] { target = gmsh_adapter::place_on_cad(raised); });
  } else {
    target = rebuilt_boundary(ctx, raised, corner);
  }
  // With vertices=fixed the linear mesh's interior vertices are held where they are:
  // only the nodes the order raising added move.
  const std::vector<bool> boundary = boundary_nodes(raised);
  std::vector<bool> held = boundary;
  if (fixed_vertices) {
    const std::vector<bool> vertex = vertex_nodes(raised);
    for (int i = 0; i < raised.num_nodes(); ++i)
      if (vertex[i] && !held[i]) {
        held[i] = true;
        target.col(i) = raised.x.col(i);
      }
  }
  DeformResult r = deform_mesh(raised, target, held, d);
  if (!r.complete && (fixed_vertices || d.reach > 0 || d.layers > 0)) {
    const std::string restricted =
        std::string(fixed_vertices ? "vertices held, " : "") +
        (d.layers > 0 ? fmt::format("within {} element layers", d.layers)
         : d.reach > 0 ? fmt::format("within reach {:g}", d.reach)
                       : std::string("whole mesh"));
    ctx.log.info("curve: the solve ({}) kept the mesh valid only up to {:.1f} % of the motion; "
                 "solving on the whole mesh with every interior node free",
                 restricted, 100 * r.reached);
    d.reach = 0;
    d.layers = 0;
    r = deform_mesh(raised, target, boundary, d);
  }
  if (!r.complete)
    throw Error(fmt::format(
        "stage 'curve': the elastic analogy ({}) kept the mesh valid only up to {:.1f} % of "
        "the boundary motion ({} triangles would become invalid); try more increments or "
        "another formulation",
        d.formulation, 100 * r.reached, r.invalid_at_failure));
  m = r.mesh;
  ctx.fields.clear();
  ctx.log.info(
      "curve: order {}, formulation {}, nu {}, posed on {} of {} triangles: {} solves, worst "
      "minJ/maxJ {:.4f}",
      p, d.formulation, d.params.poisson, r.solved_triangles, m.num_triangles(), r.solves,
      r.worst_ratio);
}

}  // namespace

Stage curve_stage() {
  std::vector<OptionSpec> options = {
      {"p", "2", "element order, 2 to " + std::to_string(kMaxOrder)},
      {"increments", "1",
       "load increments (halved where validity needs it); formulations whose terms depend on "
       "the deformation so far (force_q17, heat_*, metric_*, stiff_*) see only the straight "
       "mesh in one increment: give them 4 or more"},
      {"vertices", "fixed",
       "fixed: the linear mesh's vertices stay (boundary-layer heights kept exactly), only the "
       "nodes the order raising adds move; free: every interior node moves (the thesis)"},
      {"layers", "0",
       "0: no effect; k > 0: solve only on the elements within k element layers of the "
       "moving boundary nodes, the rest held still (as Gmsh's Mesh.HighOrderNumLayers; "
       "replaces reach)"},
      {"reach", "2",
       "0: solve on the whole mesh; r > 0: only on the triangles within r times the size of "
       "the boundary triangles of the moving boundary, the rest held still (a boundary "
       "layer's thin elements do not shrink this region); the whole mesh if that fails"},
      {"corner", "40",
       "without CAD (a .msh): boundary vertices turning more than this (degrees) stay sharp "
       "corners of the rebuilt spline curves"}};
  // Defaults: E = 1/Ae, nu = 0.49, one increment, vertices fixed, reach 2. Measured on
  // the boundary-layer meshes of scripts/bench/curving_vs_gmsh.py (plate and NACA-7526,
  // first cell 1e-3 and 1e-4, p = 2-4): worst minJ/maxJ 0.96-0.99, against 0.89-0.95
  // for E = 1, nu = 0.4 (scripts/bench/README.md). A nearly incompressible material
  // keeps the thin layer elements' areas, so the wall's curvature is carried up through
  // the layers instead of squashing the first one; 1/Ae makes the small elements stiff
  // as well; holding the vertices keeps the linear mesh and shrinks the system.
  for (auto& o : analogy_option_specs("area", "0.49")) options.push_back(std::move(o));
  return {"curve",
          "order p with boundary nodes on the CAD (or on splines rebuilt from a bare .msh), "
          "interior by the elastic analogy, valid",
          options, run};
}

}  // namespace homesh
