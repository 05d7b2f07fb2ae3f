#include "pipeline/stage_registry.h"

#include <fmt/core.h>

#include "core/error.h"
#include "pipeline/stages/curve_stage.h"
#include "pipeline/stages/info_stage.h"
#include "pipeline/stages/layers_stage.h"
#include "pipeline/stages/mesh_stage.h"
#include "pipeline/stages/optimise_stage.h"
#include "pipeline/stages/order_stage.h"
#include "pipeline/stages/quality_stage.h"
#include "pipeline/stages/rotate_stage.h"
#include "pipeline/stages/voronoi_stage.h"

namespace homesh {

const std::vector<Stage>& stages() {
  static const std::vector<Stage> table = {mesh_stage(),    order_stage(),    layers_stage(),
                                           curve_stage(),   optimise_stage(), rotate_stage(),
                                           quality_stage(), info_stage(),     voronoi_stage()};
  return table;
}

const Stage& stage(const std::string& name) {
  std::string known;
  for (const Stage& s : stages()) {
    if (s.name == name) return s;
    known += (known.empty() ? "" : ", ") + s.name;
  }
  throw Error("unknown stage '" + name + "' (stages: " + known + ")");
}

std::string stage_help(const Stage& s) {
  std::string out = fmt::format("{} - {}\n", s.name, s.summary);
  if (s.options.empty()) return out + "  (no options)\n";
  for (const auto& o : s.options)
    out += fmt::format("  {:<12} {:<10} {}\n", o.name,
                       o.default_value.empty() ? "-" : o.default_value, o.help);
  return out;
}

}  // namespace homesh
