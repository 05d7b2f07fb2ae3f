#include "pipeline/stages/optimise_stage.h"

#include <fmt/core.h>

#include <chrono>
#include <memory>

#include "core/error.h"
#include "curving/deform_mesh.h"
#include "curving/optimise_mesh.h"
#include "gmsh/cad_curves.h"
#include "gmsh/gmsh_call.h"
#include "pipeline/optimiser_options.h"

namespace homesh {
namespace {

void run(Context& ctx, const OptimiseOptions& o) {
  Mesh& m = ctx.require_mesh("optimise");
  if (m.order < 2)
    throw Error("stage 'optimise': the mesh is linear; curve it (or raise its order) first");
  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<gmsh_adapter::CadCurves> cad;
  if (ctx.has_cad)
    gmsh_adapter::gmsh_call("stage 'optimise': reading the CAD curves of " + ctx.input,
                            [&] { cad = std::make_unique<gmsh_adapter::CadCurves>(m); });
  OptimiseResult r = optimise_mesh(m, std::vector<bool>(m.num_nodes(), false), o, cad.get());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  m = std::move(r.mesh);
  ctx.fields.clear();
  ctx.log.info(
      "optimise: {} patches around {} elements below minJ/maxJ {:g}, {} kept, {} Newton steps, {} "
      "sweeps: "
      "worst "
      "minJ/maxJ {:.4f} -> {:.4f}, {} below, {} nodes sliding on curves, {:.2f} s",
      r.patches, r.poor_before, o.threshold, r.accepted, r.newton_steps, r.sweeps, r.worst_before,
      r.worst_after, r.poor_after, r.sliding_nodes, seconds);
  if (r.invalid > 0)
    ctx.log.warn("optimise: {} elements not certified valid were left as they are (no untangling)",
                 r.invalid);
  ctx.results["worst_before"] = r.worst_before;
  ctx.results["worst_after"] = r.worst_after;
  ctx.results["patches"] = r.patches;
  ctx.results["accepted"] = r.accepted;
  ctx.results["poor_before"] = r.poor_before;
  ctx.results["poor_after"] = r.poor_after;
  ctx.results["seconds"] = seconds;
}

}  // namespace

Stage optimise_stage() {
  // Defaults: OptimiseOptions' own (curving/optimise_mesh.h says why).
  OptionTable<OptimiseOptions> t;
  add_optimiser_options(t, [](OptimiseOptions& o) -> OptimiseOptions& { return o; });
  t.add("layers", &OptimiseOptions::layers, integer(0, 100),
        "rings of neighbouring elements added round the poor ones to make the patches");
  t.add("tolerance", &OptimiseOptions::tolerance, real(0),
        "a sweep lowering the patch's energy by less than this fraction ends the patch");
  t.add("vertices", &OptimiseOptions::free_vertices,
        choice<bool>({{"fixed", false}, {"free", true}}),
        "fixed: the linear mesh's vertices stay, only the nodes the order raising added move; "
        "free: interior vertices move too");
  t.add("target", &OptimiseOptions::target,
        choice<OptimiseOptions::Target>({{"straight", OptimiseOptions::Target::straight},
                                         {"ideal", OptimiseOptions::Target::ideal}}),
        "shape the distortion is measured from: straight (each element's straight-sided shape "
        "at the start) | ideal (the thesis' equilateral element)");
  t.add(
      "r", [](OptimiseOptions& o) -> double& { return o.energy.r; }, real(1, 16),
      "exponent r of Eq 3.48 (>= 2 keeps its barrier)");
  t.add(
      "alpha", [](OptimiseOptions& o) -> double& { return o.energy.alpha; }, real(0, 1e6),
      "weight of the size distortion (det J against its element mean) beside the shape "
      "distortion |W|^2 / (2 det W) - 1");
  t.add(
      "epsilon", [](OptimiseOptions& o) -> double& { return o.energy.epsilon; }, real(0, 1, "[)"),
      "barrier floor: steps refused where det J falls to this fraction of its element mean "
      "at a quadrature point (0: only det J > 0)");
  return make_stage<OptimiseOptions>(
      "optimise",
      "high-order optimiser: patches round the elements below a minJ/maxJ threshold moved to "
      "lower the thesis' distortion (Eq 3.48), each kept only if certified valid and no worse; "
      "boundary nodes sliding along their CAD curves",
      t, run, /*creates_mesh=*/false, /*handles_quads=*/true);
}

}  // namespace homesh
