#pragma once
#include "pipeline/stage.h"

namespace homesh {

/// Gmsh's meshing options the mesh stage sets (0 sizes: left to Gmsh).
struct MeshOptions {
  double size_min = 0;  ///< Mesh.MeshSizeMin
  double size_max = 0;  ///< Mesh.MeshSizeMax
  double factor = 1;    ///< Mesh.MeshSizeFactor
  int algorithm = 6;    ///< Mesh.Algorithm: 6 = frontal-Delaunay
};

/// `mesh`: a new linear triangle mesh of the input's CAD by Gmsh.
Stage mesh_stage();

}  // namespace homesh
