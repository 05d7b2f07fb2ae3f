#include "gmsh/read_model.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/check_mesh.h"
#include "core/error.h"
#include "gmsh/ungrouped_group.h"

namespace homesh::gmsh_adapter {
namespace {

// Tags are positive; MSH files store them as signed or unsigned 64-bit
// integers, so a negative tag reaches Gmsh's API as a number >= 2^63.
constexpr std::size_t kMaxTag = (std::size_t{1} << 63) - 1;

struct ElementBlock {
  int entity;
  std::vector<std::size_t> node_tags;
};

// Classification and entity structure: entities, their boundaries, physicals.
void read_entities(Mesh& m) {
  gmsh::vectorpair dim_tags;
  gmsh::model::getEntities(dim_tags);
  for (const auto& [dim, tag] : dim_tags) {
    if (dim > 2) continue;
    Entity e{dim, tag, {}};
    if (dim > 0) {
      gmsh::vectorpair bnd;
      gmsh::model::getBoundary({{dim, tag}}, bnd, false, true, false);
      for (const auto& b : bnd) e.boundary.push_back(b.second);
    }
    m.entities.push_back(e);
  }
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  for (const auto& [dim, tag] : groups) {
    if (dim > 2) continue;
    PhysicalGroup g{dim, tag, {}, {}};
    gmsh::model::getPhysicalName(dim, tag, g.name);
    if (g.name == kUngroupedName) continue;  // written for meshio only
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, g.entities);
    m.physicals.push_back(g);
  }
}

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
  read_entities(m);

  std::vector<int> types3;
  gmsh::model::mesh::getElementTypes(types3, 3);
  if (!types3.empty())
    throw Error(source + ": has 3D elements; homesh meshes planar 2D triangle meshes");

  // Nodes, entity by entity, so each node knows its classification.
  std::vector<std::pair<std::size_t, NodeClass>> tagged;
  std::vector<double> xyz;
  for (const Entity& e : m.entities) {
    std::vector<std::size_t> tags;
    std::vector<double> coord, param;
    gmsh::model::mesh::getNodes(tags, coord, param, e.dim, e.tag, false, true);
    const bool has_u = e.dim == 1 && param.size() == tags.size();
    for (std::size_t i = 0; i < tags.size(); ++i) {
      NodeClass c{e.dim, e.tag, has_u ? param[i] : std::numeric_limits<double>::quiet_NaN()};
      tagged.emplace_back(tags[i], c);
      xyz.insert(xyz.end(), coord.begin() + 3 * i, coord.begin() + 3 * i + 3);
    }
  }
  std::vector<std::size_t> perm(tagged.size());
  for (std::size_t i = 0; i < perm.size(); ++i) perm[i] = i;
  std::sort(perm.begin(), perm.end(),
            [&](std::size_t a, std::size_t b) { return tagged[a].first < tagged[b].first; });

  // Node tags may be sparse and huge: a compacting index (the sorted tags,
  // searched), never an array sized by the largest tag.
  std::vector<std::size_t> sorted_tags(perm.size());
  m.x.resize(2, static_cast<Eigen::Index>(perm.size()));
  m.node_class.resize(perm.size());
  double extent = 0, zmax = 0;
  for (std::size_t k = 0; k < perm.size(); ++k) {
    const std::size_t i = perm[k];
    const std::size_t tag = tagged[i].first;
    if (tag == 0 || tag > kMaxTag)
      throw Error(source + ": node tag " + std::to_string(static_cast<long long>(tag)) +
                  " is not a positive integer below 2^63");
    if (k > 0 && sorted_tags[k - 1] == tag)
      throw Error(source + ": node tag " + std::to_string(tag) + " is used twice");
    sorted_tags[k] = tag;
    m.x(0, k) = xyz[3 * i];
    m.x(1, k) = xyz[3 * i + 1];
    m.node_class[k] = tagged[i].second;
    extent = std::max({extent, std::abs(xyz[3 * i]), std::abs(xyz[3 * i + 1])});
    zmax = std::max(zmax, std::abs(xyz[3 * i + 2]));
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

  // Where the tags are dense (as Gmsh numbers them: at most twice as many tags as
  // nodes), a table by tag; else the sorted tags searched (a binary search per
  // element node was 0.37 of the 0.85 ms reading a 2354-triangle mesh took).
  std::vector<int> by_tag;
  if (!sorted_tags.empty() && sorted_tags.back() <= 2 * sorted_tags.size() + 1024) {
    by_tag.assign(sorted_tags.back() + 1, -1);
    for (std::size_t k = 0; k < sorted_tags.size(); ++k)
      by_tag[sorted_tags[k]] = static_cast<int>(k);
  }
  auto node_index = [&](std::size_t tag) {
    int index = -1;
    if (!by_tag.empty()) {
      if (tag < by_tag.size()) index = by_tag[tag];
    } else {
      const auto it = std::lower_bound(sorted_tags.begin(), sorted_tags.end(), tag);
      if (it != sorted_tags.end() && *it == tag) index = static_cast<int>(it - sorted_tags.begin());
    }
    if (index < 0)
      throw Error(source + ": an element refers to node " +
                  std::to_string(static_cast<long long>(tag)) + ", which the mesh does not have");
    return index;
  };
  auto fill = [&](const std::vector<ElementBlock>& blocks, int per, Eigen::MatrixXi& conn,
                  std::vector<int>& entity) {
    std::size_t count = 0;
    for (const auto& b : blocks) count += b.node_tags.size() / per;
    conn.resize(per, static_cast<Eigen::Index>(count));
    entity.clear();
    Eigen::Index col = 0;
    for (const auto& b : blocks)
      for (std::size_t k = 0; k < b.node_tags.size() / per; ++k, ++col) {
        for (int i = 0; i < per; ++i) conn(i, col) = node_index(b.node_tags[k * per + i]);
        entity.push_back(b.entity);
      }
  };
  fill(tris, triangle_node_count(order), m.tri, m.tri_entity);
  fill(quads, quad_node_count(order), m.quad, m.quad_entity);
  fill(lines, order + 1, m.line, m.line_entity);
  for (const auto& b : points)
    for (std::size_t tag : b.node_tags) {
      m.point_node.push_back(node_index(tag));
      m.point_entity.push_back(b.entity);
    }
  check_mesh(m, source);
  return m;
}

}  // namespace homesh::gmsh_adapter
