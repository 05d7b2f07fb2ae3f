#include "pipeline/stages/rotate_stage.h"

#include <fmt/core.h>

#include <algorithm>

#include "core/error.h"
#include "core/wall_curves.h"
#include "curving/deform_mesh.h"
#include "pipeline/analogy_options.h"

namespace homesh {
namespace {

// wall[i] = node i lies on a line of the curves `names` gives.
std::vector<bool> wall_nodes(const Mesh& m, const std::vector<std::string>& names) {
  const std::vector<int> curves = wall_curves(m, names, "stage 'rotate'");
  std::vector<bool> wall(static_cast<std::size_t>(m.num_nodes()), false);
  for (int k = 0; k < m.num_lines(); ++k)
    if (std::binary_search(curves.begin(), curves.end(), m.line_entity[k]))
      for (Eigen::Index j = 0; j < m.line.rows(); ++j) wall[m.line(j, k)] = true;
  if (std::find(wall.begin(), wall.end(), true) == wall.end())
    throw Error("stage 'rotate': the wall '" + names.front() + "' has no mesh lines");
  return wall;
}

void run(Context& ctx, const RotateStageOptions& o) {
  Mesh& m = ctx.require_mesh("rotate");
  const RotateOptions& r = o.rotation;
  const RotateResult res = rotate_boundary(m, wall_nodes(m, o.wall), boundary_nodes(m), r);
  m = res.mesh;
  ctx.fields.clear();
  ctx.results = {{"theta_max", res.theta_max},
                 {"steps", res.steps},
                 {"reached_max", res.reached_max},
                 {"solves", res.solves},
                 {"mean_iterations", res.mean_iterations},
                 {"worst", res.worst_ratio},
                 {"invalid_at_failure", res.invalid_at_failure},
                 {"centre_x", res.centre.x()},
                 {"centre_y", res.centre.y()}};
  if (r.solver.method == "cg")
    ctx.log.info("rotate: theta_max = {:g} deg, mean CG iterations {:.0f}", res.theta_max,
                 res.mean_iterations);
  else
    ctx.log.info("rotate: theta_max = {:g} deg", res.theta_max);
  std::string wall;
  for (const std::string& w : o.wall) wall += (wall.empty() ? "" : ",") + w;
  ctx.log.info(
      "  wall {} about ({:.6g}, {:.6g}), step {:g} deg posed on the {} mesh ({} solves each), "
      "formulation {}, nu {:g}, heat {:g}, solver {}",
      wall, res.centre.x(), res.centre.y(), r.step, r.total ? "initial" : "current",
      r.total ? 1 : r.substeps, r.formulation, r.params.poisson, r.params.heat, r.solver.method);
  ctx.log.info(
      "  {} steps, {} solves, worst minJ/maxJ {:.4f}, {}", res.steps, res.solves, res.worst_ratio,
      res.reached_max
          ? "maximum angle reached"
          : fmt::format("the next step leaves {} triangles invalid", res.invalid_at_failure));
}

}  // namespace

Stage rotate_stage() {
  // Defaults: those of RotateStageOptions and RotateOptions (curving/rotate_boundary.h).
  using O = RotateStageOptions;
  OptionTable<O> t;
  t.add("wall", &O::wall, list(),
        "the curves to rotate, comma-separated, each a curve physical group name, a curve "
        "physical group number or, if no group has that number, a curve tag");
  t.add(
      "centre", [](O& o) -> std::optional<Eigen::Vector2d>& { return o.rotation.centre; },
      point_or("auto"), "x,y, or auto: centre of the circle fitted to the wall's nodes");
  t.add(
      "step", [](O& o) -> double& { return o.rotation.step; },
      where<double>(
          real(), [](const double& h) { return h != 0; }, "must be nonzero"),
      "angle step, degrees (negative: clockwise)");
  t.add(
      "max", [](O& o) -> double& { return o.rotation.max_angle; }, real(0),
      "largest angle tried, degrees");
  t.add(
      "substeps", [](O& o) -> int& { return o.rotation.substeps; }, integer(1, 1000),
      "solves per step (pose=current)");
  t.add(
      "pose", [](O& o) -> bool& { return o.rotation.total; },
      choice<bool>({{"current", false}, {"initial", true}}),
      "pose each step on the current mesh (thesis) or the initial one");
  add_analogy_options(
      t, [](O& o) -> std::string& { return o.rotation.formulation; },
      [](O& o) -> FormulationParams& { return o.rotation.params; },
      [](O& o) -> LinearSolverOptions& { return o.rotation.solver; });
  t.check([](const O& o) { return o.wall.empty() ? "option wall is empty" : ""; });
  return make_stage<O>(
      "rotate", "turn a wall step by step (elastic analogy) until an element would become invalid",
      t, run);
}

}  // namespace homesh
