#include "gmsh/view_style.h"

#include <fmt/core.h>
#include <gmsh.h>

#include <algorithm>
#include <utility>

namespace homesh::gmsh_adapter {
namespace {

using Settings = std::vector<std::pair<std::string, double>>;

constexpr int kSubEdges = 8;  // segments Gmsh draws per high-order edge

std::string option(int view_tag, const std::string& name) {
  return "View[" + std::to_string(gmsh::view::getIndex(view_tag)) + "]." + name;
}

// Subdivisions of each element edge drawn: 2^level, enough for the curve of an
// order-p edge (p = 1: the element itself, nothing to adapt).
int recursion_level(int order) { return order <= 1 ? 0 : order == 2 ? 2 : 3; }

Settings settings(const Field& f, int order) {
  Settings s = {
      {"Visible", f.shown ? 1 : 0},
      {"ShowScale", 1},
      {"AdaptVisualizationGrid", order > 1 ? 1 : 0},
      {"MaxRecursionLevel", recursion_level(order)},
      {"TargetError", -1},  // < 0: refine uniformly (Gmsh's adaptiveData)
      {"DrawPoints", 0},
      {"DrawLines", 0},
      {"Light", 0},  // flat colours: the legend's colour is the element's
      // Element-constant: ten discrete bands; at nodes: continuous, as the values vary.
      {"IntervalsType", f.kind == Field::Kind::Element ? 3 : 2},
      {"NbIso", 10},
  };
  if (f.quality) {
    s.insert(s.end(), {{"RangeType", 2},  // custom: fixed [CustomMin, CustomMax]
                       {"CustomMin", 0},
                       {"CustomMax", 1},
                       {"SaturateValues", 1},   // invalid (< 0) drawn in the colour of 0
                       {"ColormapNumber", 21},  // inferno: 0 black, poor purple, 1 pale yellow
                       {"ColormapSwap", 0}});
  } else {
    s.insert(s.end(), {{"RangeType", 1},  // the data's own range
                       {"CustomMin", 0},
                       {"CustomMax", 1},
                       {"SaturateValues", 0},
                       {"ColormapNumber", 2},
                       {"ColormapSwap", 0}});
  }
  return s;
}

}  // namespace

const std::vector<std::string>& styled_view_options() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& [name, value] : settings(Field{}, 2)) out.push_back(name);
    return out;
  }();
  return names;
}

void style_view(int view_tag, const Field& field, int order) {
  for (const auto& [name, value] : settings(field, order))
    gmsh::option::setNumber(option(view_tag, name), value);
}

void draw_edges_curved() {
  double now = 0;
  gmsh::option::getNumber("Mesh.NumSubEdges", now);
  if (now < kSubEdges) gmsh::option::setNumber("Mesh.NumSubEdges", kSubEdges);
}

void hide_other_views(const std::vector<int>& view_tags) {
  std::vector<int> all;
  gmsh::view::getTags(all);
  for (int v : all)
    if (std::find(view_tags.begin(), view_tags.end(), v) == view_tags.end())
      gmsh::option::setNumber(option(v, "Visible"), 0);
}

std::string sidecar_options(const std::vector<int>& view_tags) {
  const std::size_t n = view_tags.size();
  std::string s =
      "// homesh display settings. Gmsh merges this file right after it reads the .msh\n"
      "// beside it, whose " +
      std::to_string(n) +
      " views are then the last ones loaded: they are addressed from the end,\n"
      "// so merging several files styles each one's own views.\n"
      "Mesh.NumSubEdges = " +
      std::to_string(kSubEdges) + ";  // draw high-order edges curved\n";
  if (n == 0) return s;
  s += fmt::format(
      "homesh_first_view = PostProcessing.NbViews - {};\n"
      "For homesh_view In {{0 : homesh_first_view - 1}}\n"
      "  View[homesh_view].Visible = 0;  // views loaded before: one colour scale shows\n"
      "EndFor\n",
      n);
  for (std::size_t i = 0; i < n; ++i) {
    std::string name;
    gmsh::option::getString(option(view_tags[i], "Name"), name);
    s += fmt::format("// {}\n", name);
    for (const std::string& o : styled_view_options()) {
      double value = 0;
      gmsh::option::getNumber(option(view_tags[i], o), value);
      s += fmt::format("View[homesh_first_view + {}].{} = {:g};\n", i, o, value);
    }
  }
  return s;
}

}  // namespace homesh::gmsh_adapter
