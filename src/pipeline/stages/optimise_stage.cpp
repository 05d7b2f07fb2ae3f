#include "pipeline/stages/optimise_stage.h"

#include <fmt/core.h>

#include <chrono>

#include "core/error.h"
#include "curving/deform_mesh.h"
#include "curving/optimise_mesh.h"

namespace homesh {
namespace {

const char* target_name(OptimiseOptions::Target t) {
  return t == OptimiseOptions::Target::ideal ? "ideal" : "straight";
}

void run(Context& ctx, const Options& opt) {
  Mesh& m = ctx.require_mesh("optimise");
  if (m.order < 2)
    throw Error("stage 'optimise': the mesh is linear; curve it (or raise its order) first");
  OptimiseOptions o;
  o.threshold = opt.get_double("threshold");
  if (!(o.threshold > 0 && o.threshold <= 1))
    throw Error(fmt::format("stage 'optimise': threshold = {:g} must be in (0, 1]", o.threshold));
  o.layers = opt.get_int("layers", 0, 100);
  o.max_sweeps = opt.get_int("sweeps", 0, 10000);
  o.tolerance = opt.get_double("tolerance");
  if (!(o.tolerance >= 0))
    throw Error(fmt::format("stage 'optimise': tolerance = {:g} must be >= 0", o.tolerance));
  o.free_vertices = opt.get_choice("vertices", {"fixed", "free"}) == "free";
  o.target = opt.get_choice("target", {"ideal", "straight"}) == "ideal"
                 ? OptimiseOptions::Target::ideal
                 : OptimiseOptions::Target::straight;
  o.energy.r = opt.get_double("r");
  if (!(o.energy.r >= 1 && o.energy.r <= 16))
    throw Error(fmt::format("stage 'optimise': r = {:g} must be in [1, 16]", o.energy.r));
  o.energy.alpha = opt.get_double("alpha");
  if (!(o.energy.alpha >= 0 && o.energy.alpha <= 1e6))
    throw Error(fmt::format("stage 'optimise': alpha = {:g} must be in [0, 1e6]", o.energy.alpha));
  o.energy.epsilon = opt.get_double("epsilon");
  if (!(o.energy.epsilon >= 0 && o.energy.epsilon < 1))
    throw Error(fmt::format("stage 'optimise': epsilon = {:g} must be in [0, 1)", o.energy.epsilon));

  const auto start = std::chrono::steady_clock::now();
  OptimiseResult r = optimise_mesh(m, boundary_nodes(m), o);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  m = std::move(r.mesh);
  ctx.fields.clear();
  ctx.log.info(
      "optimise: {} patches around {} elements below minJ/maxJ {:g}, {} kept, {} sweeps: worst "
      "minJ/maxJ {:.4f} -> {:.4f}, {} below, {:.2f} s",
      r.patches, r.poor_before, o.threshold, r.accepted, r.sweeps, r.worst_before, r.worst_after,
      r.poor_after, seconds);
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
  const OptimiseOptions d;
  return {"optimise",
          "high-order optimiser: patches round the elements below a minJ/maxJ threshold moved "
          "to lower the thesis' distortion (Eq 3.48), each kept only if certified valid and "
          "no worse; boundary nodes held",
          {{"threshold", fmt::format("{:g}", d.threshold),
            "elements whose certified minJ/maxJ is below this are optimised, in (0, 1]"},
           {"layers", std::to_string(d.layers),
            "rings of neighbouring elements added round the poor ones to make the patches"},
           {"sweeps", std::to_string(d.max_sweeps), "most node-by-node Newton sweeps per patch"},
           {"tolerance", fmt::format("{:g}", d.tolerance),
            "a sweep lowering the patch's energy by less than this fraction ends the patch"},
           {"vertices", d.free_vertices ? "free" : "fixed",
            "fixed: the linear mesh's vertices stay, only the nodes the order raising added "
            "move; free: interior vertices move too"},
           {"target", target_name(d.target),
            "shape the distortion is measured from: ideal (the thesis' equilateral element) | "
            "straight (each element's straight-sided shape at the start)"},
           {"r", fmt::format("{:g}", d.energy.r), "exponent r of Eq 3.48 (>= 2 keeps its barrier)"},
           {"alpha", fmt::format("{:g}", d.energy.alpha),
            "weight of the size distortion (det J against its element mean) beside the shape "
            "distortion |W|^2 / (2 det W) - 1"},
           {"epsilon", fmt::format("{:g}", d.energy.epsilon),
            "barrier floor: steps refused where det J falls to this fraction of its element "
            "mean at a quadrature point (0: only det J > 0)"}},
          run};
}

}  // namespace homesh
