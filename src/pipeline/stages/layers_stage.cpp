#include "pipeline/stages/layers_stage.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "layers/insert_layers.h"
#include "layers/radius_ratio.h"
#include "pipeline/analogy_options.h"

namespace homesh {
namespace {

void run(Context& ctx, const LayerOptions& o) {
  Mesh& m = ctx.require_mesh("layers");
  const int order = m.order, nodes = m.num_nodes(), triangles = m.num_triangles();
  LayerResult r = insert_layers(m, o);
  if (r.from_corners)
    ctx.log.info(
        "layers: the input is of order {}: its corners are layered and the result is "
        "linear (curve it with -m curve:p=N)",
        order);
  const std::vector<int> corner = corner_triangles(r, r.sharpest_node);
  m = std::move(r.mesh);

  const Eigen::VectorXd q = radius_ratios(m);
  Eigen::VectorXd layer(m.num_elements_2d());
  for (int e = 0; e < m.num_elements_2d(); ++e) layer(e) = r.layer[e];
  ctx.fields.clear();
  ctx.set_field({"homesh: radius ratio (Eq 4.17)", Field::Kind::Element, q.transpose()});
  ctx.set_field({"homesh: boundary layer", Field::Kind::Element, layer.transpose(), false});

  std::string walls;
  for (const std::string& w : o.walls) walls += (walls.empty() ? "" : ",") + w;
  ctx.log.info(
      "layers: {} layers on {} ({} loop(s), {} wall edges, {} fans), thickness {:.6g} "
      "(first {:g}, ratio {:g})",
      o.layers, walls, r.loops, r.wall_edges, r.fan_nodes, r.thickness, o.first, o.ratio);
  if (r.open_walls > 0)
    ctx.log.info(
        "layers: {} of the walls open: their layers end along the boundary curves at "
        "their ends, whose lines are split at the layer nodes",
        r.open_walls);
  const int shown = 5;
  for (std::size_t i = 0; i < r.thinned.size() && i < shown; ++i) {
    const ThinnedLayers& t = r.thinned[i];
    const std::string where =
        t.crossing ? fmt::format(
                         "its neighbouring normals cross {:.4g} away (a concave wall; "
                         "cross = {:g})",
                         t.gap, o.cross)
                   : fmt::format("curve {} is {:.4g} away along the normal (fill = {:g})", t.facing,
                                 t.gap, o.fill);
    ctx.log.warn(
        "layers: stack thinned to {:.0f} % ({:.4g} of {:.4g}) at ({:.6g}, {:.6g}) on curve {}, "
        "where {}; {} normal(s) thinned from ({:.6g}, {:.6g}) to ({:.6g}, {:.6g})",
        100 * t.factor, t.factor * r.thickness, r.thickness, t.tightest(0), t.tightest(1), t.curve,
        where, t.lines, t.from(0), t.from(1), t.to(0), t.to(1));
  }
  if (r.thinned.size() > shown)
    ctx.log.warn("layers: stack thinned at {} more place(s)", r.thinned.size() - shown);
  ctx.log.info(
      "layers: room opened in {} elastic step(s) (formulation {}, nu {:g}), {} free node(s) "
      "in the room removed, {} node move(s) smoothing squeezed triangles; {} -> {} "
      "triangles{}, {} -> {} nodes",
      r.push_steps, o.room.formulation, o.room.params.poisson, r.cleared, r.smoothed, triangles,
      m.num_triangles(),
      m.num_quads() > 0 ? fmt::format(" and {} quadrilaterals", m.num_quads()) : std::string(),
      nodes, m.num_nodes());
  double worst = 1, sum = 0, others = 1;
  int count = 0;
  for (int e = 0; e < m.num_elements_2d(); ++e)
    if (r.layer[e] > 0) {
      worst = std::min(worst, q(e));
      sum += q(e);
      ++count;
    } else {
      others = std::min(others, q(e));
    }
  ctx.log.info(
      "layers: radius ratio Q (Eq 4.17; of a quadrilateral, its corner triangles' least) of the "
      "{} layer {}: min {:.4f}, mean {:.4f}; of the other triangles: min {:.4f}",
      count, m.num_quads() > 0 ? "elements" : "triangles", worst, sum / std::max(count, 1), others);
  double corner_worst = 1;
  for (int e : corner) corner_worst = std::min(corner_worst, q(e));
  const double degrees = r.sharpest_angle * 180 / M_PI;
  const auto normals_there = std::count_if(r.lines.begin(), r.lines.end(), [&](const LayerLine& l) {
    return l.wall_node == r.sharpest_node;
  });
  ctx.log.info(
      "layers: at the sharpest wall node ({:.6g}, {:.6g}), {:.1f} deg ({}): min Q {:.4f} "
      "over its {} layer elements",
      m.x(0, r.sharpest_node), m.x(1, r.sharpest_node), degrees,
      normals_there > 1 ? fmt::format("fan of {} normals", normals_there) : "single normal",
      corner_worst, corner.size());
  if (o.normals.multi && r.fan_nodes == 0)
    ctx.log.warn(
        "layers: no wall node reaches fan_angle = {:g} deg (the sharpest has {:.1f} deg): "
        "single normals everywhere",
        o.normals.fan_angle, degrees);
}

}  // namespace

Stage layers_stage() {
  // Defaults: those of LayerOptions (layers/insert_layers.h) and its parts.
  OptionTable<LayerOptions> t;
  t.add("walls", &LayerOptions::walls, list(),
        "the curves the layers grow from, comma-separated, each a curve physical group name, a "
        "curve physical group number or, if no group has that number, a curve tag: closed "
        "loops, or open chains whose layers end along the boundary at their ends");
  t.add("n", &LayerOptions::layers, integer(1, 1000), "number of layers");
  t.add("first", &LayerOptions::first, real(0, INFINITY, "(]"),
        "thickness of the layer at the wall");
  t.add("ratio", &LayerOptions::ratio, real(0, INFINITY, "(]"),
        "thickness ratio of consecutive layers");
  t.add("fill", &LayerOptions::fill, real(0, 1, "(]"),
        "largest fraction of the distance along a normal to the nearest other boundary the "
        "stack may take: thinner layers where it would take more (gaps, slots), with a "
        "warning");
  t.add("cross", &LayerOptions::cross, real(0, 1, "()"),
        "largest fraction of the depth at which neighbouring normals cross (concave walls and "
        "corners) the stack may take: thinner layers where it would take more, with a warning");
  t.add("cells", &LayerOptions::quads, choice<bool>({{"triangles", false}, {"quads", true}}),
        "triangles | quads: the layer cells split into two triangles each, or kept as "
        "quadrilaterals along the wall edges (fans at sharp wall nodes stay triangles: their "
        "quads would be trapezia of minJ/maxJ 1 / (1 + ratio))");
  t.add(
      "normals", [](LayerOptions& o) -> bool& { return o.normals.multi; },
      choice<bool>({{"single", false}, {"multi", true}}),
      "single | multi (fans of normals at sharp wall nodes)");
  t.add(
      "fan", [](LayerOptions& o) -> int& { return o.normals.fan; },
      where<int>(
          integer(3, 99), [](const int& n) { return n % 2 == 1; }, "must be odd"),
      "normals per fan (odd, >= 3)");
  t.add(
      "fan_angle", [](LayerOptions& o) -> double& { return o.normals.fan_angle; },
      real(180, 360, "[)"), "domain angle (deg) from which a wall node gets a fan");
  t.add(
      "blend", [](LayerOptions& o) -> int& { return o.normals.blend; }, integer(0, 100),
      "sweeps blending the single normals along the wall (each within 30 deg of its "
      "bisector) where the wall turns by more than 30 deg; 0: every node's own bisector");
  add_analogy_options(
      t, [](LayerOptions& o) -> std::string& { return o.room.formulation; },
      [](LayerOptions& o) -> FormulationParams& { return o.room.params; },
      [](LayerOptions& o) -> LinearSolverOptions& { return o.room.solver; });
  t.check([](const LayerOptions& o) {
    return o.walls.empty() ? "give the walls, e.g. walls=aerofoil (curve physical group names "
                             "or numbers, or curve tags)"
                           : "";
  });
  return make_stage<LayerOptions>(
      "layers",
      "boundary layers on walls: room cleared and opened by the elastic analogy, geometric "
      "layers, thinned where walls are close or concave",
      t, run);
}

}  // namespace homesh
