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

std::vector<Field> read_views(const Mesh& mesh, const std::vector<std::size_t>& element_tags) {
  // Rows of an ElementNode field (core/field.h) and the nodes of element e.
  const int rows =
      mesh.num_quads() > 0 ? quad_node_count(mesh.order) : triangle_node_count(mesh.order);
  const int triangles = mesh.num_triangles(), elements = mesh.num_elements_2d();
  const auto nodes_of = [&](int e) {
    return e < triangles ? triangle_node_count(mesh.order) : quad_node_count(mesh.order);
  };
  const auto node = [&](int e, int k) {
    return e < triangles ? mesh.tri(k, e) : mesh.quad(k, e - triangles);
  };
  std::unordered_map<std::size_t, int> element_of;
  for (std::size_t e = 0; e < element_tags.size() && e < static_cast<std::size_t>(elements); ++e)
    element_of[element_tags[e]] = static_cast<int>(e);
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
      f.values = Eigen::MatrixXd::Constant(per_node ? rows : 1, elements, kNaN);
      for (std::size_t k = 0; k < tags.size(); ++k) {
        const auto it = element_of.find(tags[k]);
        if (it == element_of.end()) continue;
        const int size = per_node ? nodes_of(it->second) : 1;
        if (data[k].size() != static_cast<std::size_t>(size)) continue;
        f.values.col(it->second).head(size) =
            Eigen::Map<const Eigen::VectorXd>(data[k].data(), size);
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
      f.values = Eigen::MatrixXd::Constant(rows, elements, kNaN);
      for (int e = 0; e < elements; ++e)
        for (int k = 0; k < nodes_of(e); ++k) {
          f.values(k, e) = at_node[static_cast<std::size_t>(node(e, k))];
          found = found || !std::isnan(f.values(k, e));
        }
    }
    if (found) fields.push_back(std::move(f));
  }
  return fields;
}

}  // namespace homesh::gmsh_adapter
