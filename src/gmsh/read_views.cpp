#include "gmsh/read_views.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "core/error.h"
#include "gmsh/gmsh_call.h"
#include "gmsh/option_scope.h"

namespace homesh::gmsh_adapter {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The data of view `tag`'s first step, or false for a view without model data
// (list-based), which Gmsh is kept from reporting as an error: it is skipped.
bool model_data(int tag, std::string& type, std::vector<std::size_t>& tags,
                std::vector<std::vector<double>>& data, int& components) {
  OptionScope quiet;
  quiet.set("General.Verbosity", 0);
  try {
    double time = 0;
    gmsh_call("view " + std::to_string(tag),
              [&] { gmsh::view::getModelData(tag, 0, type, tags, data, time, components); });
  } catch (const Error&) {
    return false;
  }
  return !type.empty();
}

}  // namespace

std::vector<Field> read_views(const Mesh& mesh, const std::vector<std::size_t>& triangle_tags) {
  const int n = triangle_node_count(mesh.order);
  std::unordered_map<std::size_t, int> triangle_of;
  for (std::size_t e = 0; e < triangle_tags.size(); ++e)
    triangle_of[triangle_tags[e]] = static_cast<int>(e);
  // Node i of `mesh` is the i-th node in increasing tag order (read_model).
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, params;
  gmsh::model::mesh::getNodes(node_tags, coords, params, -1, -1, false, false);
  std::sort(node_tags.begin(), node_tags.end());

  std::vector<int> views;
  gmsh::view::getTags(views);
  std::vector<Field> fields;
  for (int view : views) {
    std::string type;
    std::vector<std::size_t> tags;
    std::vector<std::vector<double>> data;
    int components = 1;
    if (!model_data(view, type, tags, data, components) || components != 1) continue;
    Field f;
    gmsh::option::getString("View[" + std::to_string(gmsh::view::getIndex(view)) + "].Name",
                            f.name);
    bool found = false;
    if (type == "ElementData" || type == "ElementNodeData") {
      const bool per_node = type == "ElementNodeData";
      f.kind = per_node ? Field::Kind::ElementNode : Field::Kind::Element;
      f.values = Eigen::MatrixXd::Constant(per_node ? n : 1, mesh.num_triangles(), kNaN);
      for (std::size_t k = 0; k < tags.size(); ++k) {
        const auto it = triangle_of.find(tags[k]);
        if (it == triangle_of.end() || data[k].size() != static_cast<std::size_t>(f.values.rows()))
          continue;
        f.values.col(it->second) =
            Eigen::Map<const Eigen::VectorXd>(data[k].data(), f.values.rows());
        found = true;
      }
    } else if (type == "NodeData") {
      std::vector<double> at_node(node_tags.size(), kNaN);
      for (std::size_t k = 0; k < tags.size(); ++k) {
        const auto it = std::lower_bound(node_tags.begin(), node_tags.end(), tags[k]);
        if (it != node_tags.end() && *it == tags[k] && !data[k].empty())
          at_node[static_cast<std::size_t>(it - node_tags.begin())] = data[k][0];
      }
      f.kind = Field::Kind::ElementNode;
      f.values.resize(n, mesh.num_triangles());
      for (int e = 0; e < mesh.num_triangles(); ++e)
        for (int k = 0; k < n; ++k) {
          f.values(k, e) = at_node[static_cast<std::size_t>(mesh.tri(k, e))];
          found = found || !std::isnan(f.values(k, e));
        }
    }
    if (found) fields.push_back(std::move(f));
  }
  return fields;
}

}  // namespace homesh::gmsh_adapter
