#pragma once
// What reading any mesh from the current Gmsh model starts with: its entities
// and physical groups, its nodes with their classification, and the index of a
// node by its tag (gmsh/read_model.h for planar meshes, gmsh/read_volume_model.h
// for volume meshes).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/volume_mesh.h"

namespace homesh::gmsh_adapter {

/// The entities of dimension 0..max_dim of the current model, with their
/// boundaries (signed, as Gmsh's getBoundary returns them), and its physical
/// groups of those dimensions, but the one homesh adds for meshio (gmsh/ungrouped_group.h).
void read_model_entities(int max_dim, std::vector<Entity>& entities,
                         std::vector<PhysicalGroup>& physicals);

/// The nodes of `entities` in increasing tag order.
struct ModelNodes {
  std::vector<std::size_t> sorted_tags;
  /// 3 by #nodes coordinates.
  Eigen::Matrix3Xd x;
  /// The entity each node is classified on, and its parameters there (u on a
  /// curve, u and v on a surface) when the model gives them.
  std::vector<VolumeNodeClass> node_class;

  /// The index of the node tagged `tag`; homesh::Error naming `source` if none is.
  int index(std::size_t tag, const std::string& source) const;

  /// Where the tags are dense (at most twice as many as nodes, as Gmsh numbers
  /// them), the index by tag; else empty and `index` searches sorted_tags.
  std::vector<int> by_tag;
};

/// Reads the nodes of `entities` from the current model. Throws homesh::Error
/// naming `source` if a tag is 0, at least 2^63 or used twice.
ModelNodes read_model_nodes(const std::string& source, const std::vector<Entity>& entities);

/// Elements of one type on one entity, as Gmsh's getElements gives them.
struct ElementBlock {
  int entity;
  std::vector<std::size_t> node_tags;
  /// Their Gmsh element tags, where a reader keeps them to name elements.
  std::vector<std::size_t> element_tags = {};
};

/// The node indices (`per` rows, one column per element) of `blocks` and the
/// entity of each element.
void element_columns(const std::vector<ElementBlock>& blocks, int per, const ModelNodes& nodes,
                     const std::string& source, Eigen::MatrixXi& conn, std::vector<int>& entity);

/// Gmsh's properties of an element type: its name ("Triangle 6"), dimension,
/// order and number of nodes.
struct ElementType {
  std::string name;
  int dim = 0, order = 0, nodes = 0;
  bool is(const char* family) const { return name.rfind(family, 0) == 0; }
};
ElementType element_type(int type);

}  // namespace homesh::gmsh_adapter
