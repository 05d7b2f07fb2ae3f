#include "gmsh/add_model_mesh.h"

#include <algorithm>
#include <set>

namespace homesh::gmsh_adapter {

void ensure_entities(const std::vector<Entity>& entities,
                     const std::vector<PhysicalGroup>& physicals) {
  gmsh::vectorpair existing;
  gmsh::model::getEntities(existing);
  std::set<std::pair<int, int>> have(existing.begin(), existing.end());
  std::vector<Entity> missing;
  for (const Entity& e : entities)
    if (!have.count({e.dim, e.tag})) missing.push_back(e);
  std::stable_sort(missing.begin(), missing.end(),
                   [](const Entity& a, const Entity& b) { return a.dim < b.dim; });
  for (const Entity& e : missing) gmsh::model::addDiscreteEntity(e.dim, e.tag, e.boundary);

  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  std::set<std::pair<int, int>> have_groups(groups.begin(), groups.end());
  for (const PhysicalGroup& g : physicals) {
    if (have_groups.count({g.dim, g.tag})) continue;
    gmsh::model::addPhysicalGroup(g.dim, g.entities, g.tag);
    if (!g.name.empty()) gmsh::model::setPhysicalName(g.dim, g.tag, g.name);
  }
}

std::size_t add_point_elements(const std::vector<int>& node, const std::vector<int>& entity) {
  if (!node.empty()) {
    Eigen::MatrixXi conn(1, static_cast<Eigen::Index>(node.size()));
    for (std::size_t k = 0; k < node.size(); ++k) conn(0, static_cast<Eigen::Index>(k)) = node[k];
    add_elements(15, conn, entity, [](int k) { return 1 + static_cast<std::size_t>(k); });
  }
  return 1 + node.size();
}

}  // namespace homesh::gmsh_adapter
