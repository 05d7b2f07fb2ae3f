#include "gmsh/read_volume_model.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "gmsh/model_nodes.h"

namespace homesh::gmsh_adapter {
namespace {

std::string where(const ElementType& t, int type, int dim, int tag) {
  return "'" + t.name + "' (Gmsh type " + std::to_string(type) + ") on entity (" +
         std::to_string(dim) + ", " + std::to_string(tag) + ")";
}

// The first element of conn (its first `corners` rows) that repeats a corner, or -1.
Eigen::Index repeated_corner(const Eigen::MatrixXi& conn, int corners) {
  for (Eigen::Index e = 0; e < conn.cols(); ++e)
    for (int a = 0; a < corners; ++a)
      for (int b = a + 1; b < corners; ++b)
        if (conn(a, e) == conn(b, e)) return e;
  return -1;
}

}  // namespace

bool model_has_volume_mesh() {
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 3);
  return !types.empty();
}

VolumeMesh read_volume_model(const std::string& source, std::vector<std::size_t>* element_tags) {
  VolumeMesh m;
  read_model_entities(3, m.entities, m.physicals);
  const ModelNodes nodes = read_model_nodes(source, m.entities);
  if (!nodes.x.allFinite())
    throw Error(source + ": a node has a coordinate that is not a finite number");
  m.x = nodes.x;
  m.node_class = nodes.node_class;

  int order = -1;
  std::vector<ElementBlock> points, lines, tris, tets;
  for (const Entity& e : m.entities) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> etags, enodes;
    gmsh::model::mesh::getElements(types, etags, enodes, e.dim, e.tag);
    for (std::size_t k = 0; k < types.size(); ++k) {
      const ElementType t = element_type(types[k]);
      const bool tri = t.is("Triangle"), tet = t.is("Tetrahedron");
      const bool complete = (tri && t.nodes == triangle_node_count(t.order)) ||
                            (tet && t.nodes == tetrahedron_node_count(t.order)) || t.is("Line") ||
                            t.is("Point");
      if (!complete)
        throw Error(source + ": has elements of type " + where(t, types[k], e.dim, e.tag) +
                    (tri || tet ? ", incomplete (serendipity) elements"
                                : ", which homesh does not handle in 3D") +
                    "; homesh needs complete tetrahedra, triangles and lines");
      if (t.dim > 0) {
        if (order >= 0 && t.order != order)
          throw Error(source + ": mixes element orders " + std::to_string(order) + " and " +
                      std::to_string(t.order) + "; homesh needs one order throughout");
        order = t.order;
      }
      auto& blocks = t.dim == 0 ? points : t.dim == 1 ? lines : t.dim == 2 ? tris : tets;
      blocks.push_back({e.tag, std::move(enodes[k]), std::move(etags[k])});
    }
  }
  if (tets.empty()) throw Error(source + ": has no tetrahedra (no 3D mesh)");
  if (order > kMaxTetrahedronOrder)
    throw Error(source + ": has tetrahedra of order " + std::to_string(order) +
                "; homesh handles orders 1 to " + std::to_string(kMaxTetrahedronOrder));
  m.order = order;
  element_columns(tets, tetrahedron_node_count(order), nodes, source, m.tet, m.tet_entity);
  element_columns(tris, triangle_node_count(order), nodes, source, m.tri, m.tri_entity);
  element_columns(lines, order + 1, nodes, source, m.line, m.line_entity);
  for (const auto& b : points)
    for (std::size_t tag : b.node_tags) {
      m.point_node.push_back(nodes.index(tag, source));
      m.point_entity.push_back(b.entity);
    }
  const auto check = [&](const Eigen::MatrixXi& conn, int corners,
                         const std::vector<ElementBlock>& blocks, const char* kind) {
    Eigen::Index e = repeated_corner(conn, corners);
    if (e < 0) return;
    for (const ElementBlock& b : blocks) {
      if (e < static_cast<Eigen::Index>(b.element_tags.size()))
        throw Error(source + ": " + kind + " " + std::to_string(b.element_tags[e]) +
                    " repeats a corner node");
      e -= static_cast<Eigen::Index>(b.element_tags.size());
    }
  };
  check(m.tet, 4, tets, "tetrahedron");
  check(m.tri, 3, tris, "triangle");
  check(m.line, 2, lines, "line");
  const std::vector<int> perm = group_by_entity(m);
  if (element_tags) {
    element_tags->clear();
    for (const ElementBlock& b : tets)
      element_tags->insert(element_tags->end(), b.element_tags.begin(), b.element_tags.end());
    if (!perm.empty()) {
      std::vector<std::size_t> sorted(perm.size());
      for (std::size_t k = 0; k < perm.size(); ++k) sorted[k] = (*element_tags)[perm[k]];
      *element_tags = std::move(sorted);
    }
  }
  return m;
}

}  // namespace homesh::gmsh_adapter
