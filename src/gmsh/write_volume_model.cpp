#include "gmsh/write_volume_model.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"
#include "gmsh/add_model_mesh.h"

namespace homesh::gmsh_adapter {
namespace {

void add_nodes(const VolumeMesh& m) {
  std::map<std::pair<int, int>, std::vector<int>> by_entity;
  for (int i = 0; i < m.num_nodes(); ++i)
    by_entity[{m.node_class[i].dim, m.node_class[i].tag}].push_back(i);
  for (const auto& [entity, nodes] : by_entity) {
    std::vector<std::size_t> tags;
    std::vector<double> coord, param;
    const int dim = entity.first;
    bool all = dim == 1 || dim == 2;
    for (int i : nodes) {
      tags.push_back(static_cast<std::size_t>(i) + 1);
      coord.insert(coord.end(), {m.x(0, i), m.x(1, i), m.x(2, i)});
      const VolumeNodeClass& c = m.node_class[i];
      all = all && std::isfinite(c.u) && (dim == 1 || std::isfinite(c.v));
      param.push_back(c.u);
      if (dim == 2) param.push_back(c.v);
    }
    if (!all) param.clear();
    gmsh::model::mesh::addNodes(dim, entity.second, tags, coord, param);
  }
}

}  // namespace

ModelTags write_volume_model(const VolumeMesh& m) {
  const auto grouped = [](const std::vector<int>& e) { return std::is_sorted(e.begin(), e.end()); };
  if (!grouped(m.tet_entity) || !grouped(m.tri_entity) || !grouped(m.line_entity))
    throw Error("write_volume_model: the elements are not grouped by entity (group_by_entity)");
  gmsh::model::mesh::clear();
  ensure_entities(m.entities, m.physicals);
  add_nodes(m);

  ModelTags tags;
  const auto after = [](std::size_t first) {
    return [first](int k) { return first + static_cast<std::size_t>(k); };
  };
  tags.first_line = add_point_elements(m.point_node, m.point_entity);
  const std::size_t first_tri = tags.first_line + static_cast<std::size_t>(m.num_lines());
  tags.first_triangle = first_tri + static_cast<std::size_t>(m.num_triangles());
  tags.triangles = m.num_tetrahedra();
  tags.element.resize(static_cast<std::size_t>(m.num_tetrahedra()));
  for (int e = 0; e < m.num_tetrahedra(); ++e) tags.element[e] = m.tetrahedron_tag(e);
  using gmsh::model::mesh::getElementType;
  if (m.num_lines() > 0)
    add_elements(getElementType("Line", m.order), m.line, m.line_entity, after(tags.first_line));
  if (m.num_triangles() > 0)
    add_elements(getElementType("Triangle", m.order), m.tri, m.tri_entity, after(first_tri));
  add_elements(getElementType("Tetrahedron", m.order), m.tet, m.tet_entity,
               after(tags.first_triangle));
  return tags;
}

}  // namespace homesh::gmsh_adapter
