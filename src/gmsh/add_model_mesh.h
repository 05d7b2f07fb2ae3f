#pragma once
// The pieces of writing a core mesh into the current Gmsh model that planar
// and volume meshes share (gmsh/write_model.h, gmsh/write_volume_model.h).
#include <gmsh.h>

#include <Eigen/Core>
#include <map>
#include <vector>

#include "core/mesh.h"

namespace homesh::gmsh_adapter {

/// Adds the entities (as discrete entities, lower dimensions first) and the
/// physical groups the current model lacks; those it has are kept.
void ensure_entities(const std::vector<Entity>& entities,
                     const std::vector<PhysicalGroup>& physicals);

/// Adds the columns of `conn` (node indices, node i has tag i + 1) as elements
/// of Gmsh type `type`, grouped by entity; column k gets tag tag(k).
template <class Tag>
void add_elements(int type, const Eigen::MatrixXi& conn, const std::vector<int>& entity, Tag tag) {
  std::map<int, std::pair<std::vector<std::size_t>, std::vector<std::size_t>>> by_entity;
  for (Eigen::Index k = 0; k < conn.cols(); ++k) {
    auto& [tags, nodes] = by_entity[entity[k]];
    tags.push_back(tag(static_cast<int>(k)));
    for (Eigen::Index i = 0; i < conn.rows(); ++i)
      nodes.push_back(static_cast<std::size_t>(conn(i, k)) + 1);
  }
  for (const auto& [e, data] : by_entity)
    gmsh::model::mesh::addElementsByType(e, type, data.first, data.second);
}

/// Adds the point elements (Gmsh type 15) on nodes `node` of entities `entity`,
/// tags 1 .. #points; returns the tag after them (the first line's).
std::size_t add_point_elements(const std::vector<int>& node, const std::vector<int>& entity);

}  // namespace homesh::gmsh_adapter
