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

  Mesh raised = raise_order(m, p);
  Eigen::Matrix2Xd target;
  if (ctx.has_cad) {
    gmsh_adapter::gmsh_call("stage 'curve': placing nodes on the CAD of " + ctx.input,
                            [&] { target = gmsh_adapter::place_on_cad(raised); });
  } else {
    target = rebuilt_boundary(ctx, raised, corner);
  }
  const DeformResult r = deform_mesh(raised, target, boundary_nodes(raised), d);
  if (!r.complete)
    throw Error(fmt::format(
        "stage 'curve': the elastic analogy ({}) kept the mesh valid only up to {:.1f} % of "
        "the boundary motion ({} triangles would become invalid); try more increments or "
        "another formulation",
        d.formulation, 100 * r.reached, r.invalid_at_failure));
  m = r.mesh;
  ctx.fields.clear();
  ctx.log.info("curve: order {}, formulation {}, nu {}: {} solves, worst minJ/maxJ {:.4f}", p,
               d.formulation, d.params.poisson, r.solves, r.worst_ratio);
}

}  // namespace

Stage curve_stage() {
  std::vector<OptionSpec> options = {
      {"p", "2", "element order, 2 to " + std::to_string(kMaxOrder)},
      {"increments", "4", "load increments (halved where validity needs it)"},
      {"corner", "40",
       "without CAD (a .msh): boundary vertices turning more than this (degrees) stay sharp "
       "corners of the rebuilt spline curves"}};
  for (auto& o : analogy_option_specs()) options.push_back(std::move(o));
  return {"curve",
          "order p with boundary nodes on the CAD (or on splines rebuilt from a bare .msh), "
          "interior by the elastic analogy, valid",
          options, run};
}

}  // namespace homesh
