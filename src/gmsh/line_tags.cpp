#include "gmsh/line_tags.h"

#include <gmsh.h>

#include <string>

#include "core/error.h"

namespace homesh::gmsh_adapter {

std::vector<std::size_t> line_tags(const Mesh& mesh) {
  std::vector<std::size_t> tags;
  for (const Entity& e : mesh.entities) {
    if (e.dim != 1) continue;
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> etags, enodes;
    gmsh::model::mesh::getElements(types, etags, enodes, e.dim, e.tag);
    for (const auto& block : etags) tags.insert(tags.end(), block.begin(), block.end());
  }
  if (tags.size() != static_cast<std::size_t>(mesh.num_lines()))
    throw Error("the current Gmsh model has " + std::to_string(tags.size()) +
                " line elements, but its mesh was read with " + std::to_string(mesh.num_lines()));
  return tags;
}

}  // namespace homesh::gmsh_adapter
