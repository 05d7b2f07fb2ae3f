#include "gmsh/write_model.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"
#include "gmsh/add_model_mesh.h"

namespace homesh::gmsh_adapter {
namespace {

bool is_cad_curve(int tag) {
  std::string type;
  gmsh::model::getType(1, tag, type);
  return type.rfind("Discrete", 0) != 0;
}

void add_nodes(const Mesh& m) {
  std::map<std::pair<int, int>, std::vector<int>> by_entity;
  for (int i = 0; i < m.num_nodes(); ++i)
    by_entity[{m.node_class[i].dim, m.node_class[i].tag}].push_back(i);
  for (const auto& [entity, nodes] : by_entity) {
    std::vector<std::size_t> tags;
    std::vector<double> coord, param;
    bool all_u = entity.first == 1;
    for (int i : nodes) {
      tags.push_back(static_cast<std::size_t>(i) + 1);
      coord.insert(coord.end(), {m.x(0, i), m.x(1, i), 0.0});
      all_u = all_u && std::isfinite(m.node_class[i].u);
      param.push_back(m.node_class[i].u);
    }
    if (!all_u && entity.first == 1 && is_cad_curve(entity.second)) {
      // Nodes a stage placed on a curve without its parameter (layers' nodes
      // along the boundary curves where a wall ends): Gmsh's projection gives
      // it, so a file saved with Mesh.SaveParametric keeps every node's.
      for (std::size_t k = 0; k < nodes.size(); ++k)
        if (!std::isfinite(param[k])) {
          std::vector<double> u;
          gmsh::model::getParametrization(1, entity.second, {coord[3 * k], coord[3 * k + 1], 0.0},
                                          u);
          param[k] = u.at(0);
        }
      all_u = std::all_of(param.begin(), param.end(), [](double u) { return std::isfinite(u); });
    }
    if (!all_u) param.clear();
    gmsh::model::mesh::addNodes(entity.first, entity.second, tags, coord, param);
  }
}

}  // namespace

ModelTags write_model(const Mesh& m) {
  gmsh::model::mesh::clear();
  ensure_entities(m.entities, m.physicals);
  add_nodes(m);

  ModelTags tags;
  const auto after = [](std::size_t first) {
    return [first](int k) { return first + static_cast<std::size_t>(k); };
  };
  tags.first_line = add_point_elements(m.point_node, m.point_entity);
  tags.first_triangle = tags.first_line + static_cast<std::size_t>(m.num_lines());
  tags.triangles = m.num_triangles();
  // Mesh::triangle_tag numbers the 2D elements in file order only if they are
  // grouped by entity (core/group_by_entity.h): otherwise tags could repeat.
  if (m.num_quads() > 0 && !(std::is_sorted(m.tri_entity.begin(), m.tri_entity.end()) &&
                             std::is_sorted(m.quad_entity.begin(), m.quad_entity.end())))
    throw Error(
        "write_model: the triangles and quadrilaterals are not grouped by entity "
        "(group_by_entity)");
  tags.element.resize(static_cast<std::size_t>(m.num_elements_2d()));
  for (int e = 0; e < m.num_elements_2d(); ++e) tags.element[e] = m.triangle_tag(e);
  if (m.num_lines() > 0)
    add_elements(gmsh::model::mesh::getElementType("Line", m.order), m.line, m.line_entity,
                 after(tags.first_line));
  add_elements(gmsh::model::mesh::getElementType("Triangle", m.order), m.tri, m.tri_entity,
               [&](int e) { return tags.element[e]; });
  if (m.num_quads() > 0)
    add_elements(gmsh::model::mesh::getElementType("Quadrangle", m.order), m.quad, m.quad_entity,
                 [&](int q) { return tags.element[m.num_triangles() + q]; });
  return tags;
}

}  // namespace homesh::gmsh_adapter
