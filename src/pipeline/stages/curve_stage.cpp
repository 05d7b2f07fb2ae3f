#include "pipeline/stages/curve_stage.h"

#include <fmt/core.h>

#include "core/error.h"
#include "core/raise_order.h"
#include "curving/deform_mesh.h"
#include "pipeline/analogy_options.h"
#include "gmsh/cad_boundary.h"
#include "gmsh/gmsh_call.h"

namespace homesh {
namespace {

void run(Context& ctx, const Options& opt) {
  Mesh& m = ctx.require_mesh("curve");
  if (!ctx.has_cad)
    throw Error("stage 'curve': " + ctx.input +
                " has no CAD curves to curve onto (give the .geo/.step/.brep)");
  const int p = opt.get_int("p", 2, kMaxOrder);
  const AnalogyChoice analogy = read_analogy_options(opt, "curve");
  DeformOptions d;
  d.formulation = analogy.formulation;
  d.params = analogy.params;
  d.solver = analogy.solver;
  d.increments = opt.get_int("increments", 1, 1000);

  Mesh raised = raise_order(m, p);
  Eigen::Matrix2Xd target;
  gmsh_adapter::gmsh_call("stage 'curve': placing nodes on the CAD of " + ctx.input,
                          [&] { target = gmsh_adapter::place_on_cad(raised); });
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
      {"increments", "4", "load increments (halved where validity needs it)"}};
  for (auto& o : analogy_option_specs()) options.push_back(std::move(o));
  return {"curve",
          "order p with boundary nodes on the CAD, interior by the elastic analogy, valid",
          options, run};
}

}  // namespace homesh
