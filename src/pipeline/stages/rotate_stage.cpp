#include "pipeline/stages/rotate_stage.h"

#include "pipeline/analogy_options.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "curving/deform_mesh.h"
#include "curving/rotate_boundary.h"
#include "fem/preconditioner.h"

namespace homesh {
namespace {

// wall[i] = node i lies on a line of the physical curve groups called `names`.
std::vector<bool> wall_nodes(const Mesh& m, const std::vector<std::string>& names) {
  if (names.empty()) throw Error("stage 'rotate': option wall is empty");
  std::vector<int> curves;
  std::string known;
  for (const std::string& name : names) {
    bool found = false;
    for (const PhysicalGroup& g : m.physicals) {
      if (g.dim != 1) continue;
      if (g.name == name) {
        curves.insert(curves.end(), g.entities.begin(), g.entities.end());
        found = true;
      }
    }
    if (found) continue;
    for (const PhysicalGroup& g : m.physicals)
      if (g.dim == 1) known += (known.empty() ? "" : ", ") + g.name;
    throw Error("stage 'rotate': no physical curve named '" + name + "' (physical curves: " +
                (known.empty() ? "none" : known) + ")");
  }
  std::vector<bool> wall(static_cast<std::size_t>(m.num_nodes()), false);
  for (int k = 0; k < m.num_lines(); ++k)
    if (std::find(curves.begin(), curves.end(), m.line_entity[k]) != curves.end())
      for (Eigen::Index j = 0; j < m.line.rows(); ++j) wall[m.line(j, k)] = true;
  if (std::find(wall.begin(), wall.end(), true) == wall.end())
    throw Error("stage 'rotate': the wall '" + names.front() + "' has no mesh lines");
  return wall;
}

Eigen::Vector2d centre(const Mesh& m, const std::vector<bool>& wall, const Options& opt) {
  const std::vector<std::string> c = opt.get_list("centre");
  if (c.size() == 1 && c[0] == "auto") {
    Eigen::Matrix2Xd points(2, std::count(wall.begin(), wall.end(), true));
    for (int i = 0, k = 0; i < m.num_nodes(); ++i)
      if (wall[i]) points.col(k++) = m.x.col(i);
    return fitted_circle_centre(points);
  }
  if (c.size() != 2) throw Error("stage 'rotate': option centre must be auto or x,y");
  Eigen::Vector2d x;
  for (int k = 0; k < 2; ++k) {
    std::size_t used = 0;
    try {
      x(k) = std::stod(c[k], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != c[k].size() || !std::isfinite(x(k)))
      throw Error("stage 'rotate': option centre=" + opt.get_string("centre") +
                  ": not two numbers x,y");
  }
  return x;
}

void run(Context& ctx, const Options& opt) {
  Mesh& m = ctx.require_mesh("rotate");
  const std::vector<bool> wall = wall_nodes(m, opt.get_list("wall"));
  RotateOptions r;
  r.centre = centre(m, wall, opt);
  r.step = opt.get_double("step");
  if (r.step == 0) throw Error("stage 'rotate': option step must be nonzero");
  r.max_angle = opt.get_double("max");
  if (!(r.max_angle >= 0)) throw Error("stage 'rotate': option max must be >= 0");
  r.substeps = opt.get_int("substeps", 1, 1000);
  const std::string pose = opt.get_choice("pose", {"current", "initial"});
  r.total = pose == "initial";
  const AnalogyChoice analogy = read_analogy_options(opt, "rotate");
  r.formulation = analogy.formulation;
  r.params = analogy.params;
  r.solver = analogy.solver;

  const RotateResult res = rotate_boundary(m, wall, boundary_nodes(m), r);
  m = res.mesh;
  ctx.fields.clear();
  ctx.results = {{"theta_max", res.theta_max},
                 {"steps", res.steps},
                 {"reached_max", res.reached_max ? 1.0 : 0.0},
                 {"solves", res.solves},
                 {"mean_iterations", res.mean_iterations},
                 {"worst_ratio", res.worst_ratio},
                 {"invalid_at_failure", res.invalid_at_failure},
                 {"centre_x", r.centre.x()},
                 {"centre_y", r.centre.y()}};
  if (r.solver.method == "cg")
    ctx.log.info("rotate: theta_max = {:g} deg, mean CG iterations {:.0f}", res.theta_max,
                 res.mean_iterations);
  else
    ctx.log.info("rotate: theta_max = {:g} deg", res.theta_max);
  ctx.log.info(
      "  wall {} about ({:.6g}, {:.6g}), step {:g} deg posed on the {} mesh ({} solves each), "
      "formulation {}, nu {:g}, heat {:g}, solver {}",
      opt.get_string("wall"), r.centre.x(), r.centre.y(), r.step, pose,
      r.total ? 1 : r.substeps, r.formulation, r.params.poisson, r.params.heat, r.solver.method);
  ctx.log.info("  {} steps, {} solves, worst minJ/maxJ {:.4f}, {}", res.steps, res.solves,
               res.worst_ratio,
               res.reached_max ? "maximum angle reached"
                               : fmt::format("the next step leaves {} triangles invalid",
                                             res.invalid_at_failure));
}

}  // namespace

Stage rotate_stage() {
  std::vector<OptionSpec> options = {
      {"wall", "hole", "physical curve group(s) to rotate, comma-separated"},
      {"centre", "auto", "x,y, or auto: centre of the circle fitted to the wall's nodes"},
      {"step", "1", "angle step, degrees (negative: clockwise)"},
      {"max", "360", "largest angle tried, degrees"},
      {"substeps", "1", "solves per step (pose=current)"},
      {"pose", "current", "pose each step on the current mesh (thesis) or the initial one"}};
  for (auto& o : analogy_option_specs()) options.push_back(std::move(o));
  return {"rotate",
          "turn a wall step by step (elastic analogy) until an element would become invalid",
          options, run};
}

}  // namespace homesh
