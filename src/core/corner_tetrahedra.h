#pragma once
// The tetrahedra at each corner node of a volume mesh, in compressed rows.
#include <vector>

#include "core/volume_mesh.h"

namespace homesh {

struct CornerTetrahedra {
  /// Tetrahedra at node i: list[start[i] .. start[i+1]), increasing (#nodes + 1 starts).
  std::vector<int> start, list;
  explicit CornerTetrahedra(const VolumeMesh& m);
};

/// `in` (#tetrahedra flags) grown by `rings` layers: each layer adds the
/// tetrahedra sharing a corner with one already in.
void grow_by_corners(const VolumeMesh& m, const CornerTetrahedra& at, int rings,
                     std::vector<char>& in);

}  // namespace homesh
