#include "gmsh/ungrouped_group.h"

#include <gmsh.h>

#include <algorithm>

namespace homesh::gmsh_adapter {
namespace {

bool has_elements(int dim, int tag) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, node_tags;
  gmsh::model::mesh::getElements(types, element_tags, node_tags, dim, tag);
  return std::any_of(element_tags.begin(), element_tags.end(),
                     [](const auto& t) { return !t.empty(); });
}

}  // namespace

UngroupedGroups::UngroupedGroups() {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  if (groups.empty()) return;
  for (int dim = 0; dim <= 2; ++dim) {
    gmsh::vectorpair entities;
    gmsh::model::getEntities(entities, dim);
    std::vector<int> ungrouped;
    for (const auto& [d, tag] : entities) {
      std::vector<int> physicals;
      gmsh::model::getPhysicalGroupsForEntity(d, tag, physicals);
      if (physicals.empty() && has_elements(d, tag)) ungrouped.push_back(tag);
    }
    if (ungrouped.empty()) continue;
    const int tag = gmsh::model::addPhysicalGroup(dim, ungrouped);
    gmsh::model::setPhysicalName(dim, tag, kUngroupedName);
    added_.emplace_back(dim, tag);
  }
}

UngroupedGroups::~UngroupedGroups() {
  if (added_.empty()) return;
  try {
    gmsh::model::removePhysicalGroups(added_);
    gmsh::model::removePhysicalName(kUngroupedName);
  } catch (...) {  // Gmsh's own failure: the groups stay in the model, the file is written
  }
}

}  // namespace homesh::gmsh_adapter
