#pragma once
// The curves a user names as walls (layers' walls=, rotate's wall=), in the
// words of a Gmsh user: a physical group's name, a physical group's number,
// or an elementary curve's tag.
#include <string>
#include <vector>

#include "core/mesh.h"

namespace homesh {

/// Curve tags of the walls named in `walls`, sorted, without repeats. Each
/// entry is, in this order of precedence: the name of physical groups of
/// dimension 1 (all their curves), the number of a physical group of
/// dimension 1 (its curves), or the tag of a curve of m. Throws
/// homesh::Error, prefixed by `context` ("layers"), naming an entry that is
/// none of these, with the known curve groups.
std::vector<int> wall_curves(const Mesh& m, const std::vector<std::string>& walls,
                             const std::string& context = "layers");

}  // namespace homesh
