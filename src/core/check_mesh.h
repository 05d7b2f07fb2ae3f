#pragma once
// Sanity checks of a mesh handed to homesh, before any stage works on it.
#include <string>

#include "core/mesh.h"

namespace homesh {

/// Throws homesh::Error naming `source`, the triangle (1-based) and its
/// centroid if a node coordinate is not finite or beyond
/// limits::kMaxCoordinate, an edge is shared by three or more elements, a triangle repeats a
/// corner, has (near) zero area or is inverted (its corners clockwise: Gmsh orders triangles
/// counter-clockwise; a curved element only if its curved boundary runs clockwise too), or two
/// triangles have the same corners; the same for quadrilaterals (an edge counts triangles and
/// quadrilaterals). Curved elements whose corners or boundary are fine but whose det J changes
/// sign inside pass: the quality stage reports them and output refuses them.
void check_mesh(const Mesh& m, const std::string& source);

}  // namespace homesh
