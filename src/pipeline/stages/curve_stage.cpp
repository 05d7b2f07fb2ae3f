#include "pipeline/stages/curve_stage.h"

#include <fmt/core.h>

#include "core/error.h"
#include "core/raise_order.h"
#include "curving/deform_mesh.h"
#include "fem/linear_solver.h"
#include "gmsh/cad_boundary.h"
#include "gmsh/gmsh_call.h"

namespace homesh {
namespace {

std::string formulation_names() {
  std::string names;
  for (const auto& f : analogy_formulations()) names += (names.empty() ? "" : " | ") + f.name;
  return names;
}

void run(Context& ctx, const Options& opt) {
  Mesh& m = ctx.require_mesh("curve");
  if (!ctx.has_cad)
    throw Error("stage 'curve': " + ctx.input +
                " has no CAD curves to curve onto (give the .geo/.step/.brep)");
  const int p = opt.get_int("p", 2, kMaxOrder);
  DeformOptions d;
  d.formulation = analogy_formulation(opt.get_string("formulation")).name;
  d.params.poisson = opt.get_double("nu");
  if (!(d.params.poisson > -1 && d.params.poisson < 0.5))
    throw Error("stage 'curve': option nu must be in (-1, 0.5)");
  d.params.heat = opt.get_double("heat");
  d.increments = opt.get_int("increments", 1, 1000);
  d.solver.method = opt.get_string("solver");

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
  return {"curve",
          "order p with boundary nodes on the CAD, interior by the elastic analogy, valid",
          {{"p", "2", "element order, 2 to " + std::to_string(kMaxOrder)},
           {"formulation", "plain", formulation_names()},
           {"nu", "0.4", "Poisson's ratio"},
           {"heat", "1", "scale of the added force/heat terms (> 0 expands hot elements)"},
           {"increments", "4", "load increments (halved where validity needs it)"},
           {"solver", "ldlt", "linear solver: ldlt | cg (| cholmod)"}},
          run};
}

}  // namespace homesh
