#pragma once
// Gmsh's 2D mesher run in a child process: a mesh size a million times too
// small (`-m mesh:factor=1e-9`) makes Gmsh mesh for hours or fill the memory;
// in a child, capped in time, memory and element count, it ends in a clear
// error instead, and the mesh of a run within the caps comes back exactly (the
// same node and element tags, coordinates and parametric coordinates).
#include <cstddef>
#include <string>

#include "gmsh/child_process.h"

namespace homesh::gmsh_adapter {

struct MeshingLimits {
  std::size_t max_elements =
      0;              ///< boundary lines after 1D, triangles after 2D, tetrahedra after 3D
  ChildLimits child;  ///< memory and wall time of the mesher
  /// 2, or 3 for a model with volumes (issue 24): generate(3) after generate(2).
  int dim = 2;
};

/// Replaces the current model's mesh by Gmsh's `generate(limits.dim)` of it with the
/// mesh options already set, run in a child process within `limits`. Throws
/// homesh::Error naming `subject` (the input) when Gmsh fails, crashes or
/// exceeds a limit, saying which; the model's mesh is then left as it was.
void generate_in_child(const std::string& subject, const MeshingLimits& limits);

/// 3/4 of the machine's physical memory, bytes: the default memory cap.
std::uint64_t default_memory_cap();

}  // namespace homesh::gmsh_adapter
