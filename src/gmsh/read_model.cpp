#include "gmsh/read_model.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/check_mesh.h"
#include "core/error.h"
#include "gmsh/model_nodes.h"

namespace homesh::gmsh_adapter {
namespace {

bool is_quadrilateral(int type) {
  std::string name;
  int dim, order, num_nodes, num_primary;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(type, name, dim, order, num_nodes, local, num_primary);
  return name.rfind("Quadrilateral", 0) == 0;
}

}  // namespace

bool model_has_mesh() {
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 2);
  return !types.empty();
}

bool model_has_cad() {
  gmsh::vectorpair dim_tags;
  gmsh::model::getEntities(dim_tags);
  for (const auto& [dim, tag] : dim_tags) {
    if (dim == 0) continue;  // model points read from a .msh are typed "Point" too
    std::string type;
    gmsh::model::getType(dim, tag, type);
    if (type.rfind("Discrete", 0) != 0) return true;
  }
  return false;
}

Mesh read_model(const std::string& source, std::vector<std::size_t>* element_tags) {
  Mesh m;
  read_model_entities(2, m.entities, m.physicals);

  std::vector<int> types3;
  gmsh::model::mesh::getElementTypes(types3, 3);
  if (!types3.empty())
    throw Error(source + ": has 3D elements; homesh meshes planar 2D triangle meshes");

  const ModelNodes nodes = read_model_nodes(source, m.entities);
  m.x = nodes.x.topRows<2>();
  m.node_class.resize(nodes.node_class.size());
  double extent = 0, zmax = 0;
  for (std::size_t k = 0; k < nodes.node_class.size(); ++k) {
    const VolumeNodeClass& c = nodes.node_class[k];
    m.node_class[k] = {c.dim, c.tag, c.dim == 1 ? c.u : std::numeric_limits<double>::quiet_NaN()};
    const auto i = static_cast<Eigen::Index>(k);
    extent = std::max({extent, std::abs(nodes.x(0, i)), std::abs(nodes.x(1, i))});
    zmax = std::max(zmax, std::abs(nodes.x(2, i)));
  }
  if (zmax > 1e-10 * std::max(1.0, extent))
    throw Error(source + ": nodes lie off the plane z = 0 (|z| up to " + std::to_string(zmax) +
                "); homesh meshes planar 2D domains");

  // Elements, entity by entity; all 1D and 2D elements must share one order.
  int order = -1;
  auto take = [&](int dim, int tag, int type, const std::vector<std::size_t>& nodes,
                  std::vector<ElementBlock>& blocks) {
    std::string name;
    int edim, eorder, num_nodes, num_primary;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(type, name, edim, eorder, num_nodes, local,
                                            num_primary);
    const bool triangle = name.rfind("Triangle", 0) == 0;
    const bool quad = name.rfind("Quadrilateral", 0) == 0;
    const bool complete = (triangle && num_nodes == triangle_node_count(eorder)) ||
                          (quad && num_nodes == quad_node_count(eorder));
    const std::string what = "'" + name + "' (Gmsh type " + std::to_string(type) + ") on entity (" +
                             std::to_string(dim) + ", " + std::to_string(tag) + ")";
    if (dim == 2 && (triangle || quad) && !complete)
      throw Error(source + ": has elements of type " + what +
                  ", incomplete (serendipity) elements; homesh needs complete Lagrange " +
                  "triangles and quadrilaterals ((p+1)(p+2)/2 and (p+1)^2 nodes)");
    const bool ok = (dim == 0 && type == 15) || (dim == 1 && name.rfind("Line", 0) == 0) ||
                    (dim == 2 && complete);
    if (!ok)
      throw Error(source + ": has elements of type " + what +
                  "; homesh needs complete triangles, quadrilaterals and lines");
    if (dim > 0) {
      if (order >= 0 && eorder != order)
        throw Error(source + ": mixes element orders " + std::to_string(order) + " and " +
                    std::to_string(eorder) + "; homesh needs one order throughout");
      order = eorder;
    }
    blocks.push_back({tag, nodes});
  };
  std::vector<ElementBlock> points, lines, tris, quads;
  std::vector<std::size_t> triangle_tags, quad_tags;
  for (const Entity& e : m.entities) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> etags, enodes;
    gmsh::model::mesh::getElements(types, etags, enodes, e.dim, e.tag);
    for (std::size_t t = 0; t < types.size(); ++t) {
      const bool quad = e.dim == 2 && is_quadrilateral(types[t]);
      take(e.dim, e.tag, types[t], enodes[t],
           e.dim == 0   ? points
           : e.dim == 1 ? lines
           : quad       ? quads
                        : tris);
      if (e.dim != 2) continue;
      std::vector<std::size_t>& tags = quad ? quad_tags : triangle_tags;
      tags.insert(tags.end(), etags[t].begin(), etags[t].end());
    }
  }
  if (tris.empty() && quads.empty())
    throw Error(source + ": has no triangles or quadrilaterals (no 2D mesh)");
  if (element_tags) {
    *element_tags = std::move(triangle_tags);
    element_tags->insert(element_tags->end(), quad_tags.begin(), quad_tags.end());
  }
  m.order = order;

  auto fill = [&](const std::vector<ElementBlock>& blocks, int per, Eigen::MatrixXi& conn,
                  std::vector<int>& entity) {
    element_columns(blocks, per, nodes, source, conn, entity);
  };
  fill(tris, triangle_node_count(order), m.tri, m.tri_entity);
  fill(quads, quad_node_count(order), m.quad, m.quad_entity);
  fill(lines, order + 1, m.line, m.line_entity);
  for (const auto& b : points)
    for (std::size_t tag : b.node_tags) {
      m.point_node.push_back(nodes.index(tag, source));
      m.point_entity.push_back(b.entity);
    }
  check_mesh(m, source);
  return m;
}

}  // namespace homesh::gmsh_adapter
