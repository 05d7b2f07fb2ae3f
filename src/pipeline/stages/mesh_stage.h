#pragma once
#include "pipeline/stage.h"

namespace homesh {

/// Gmsh's meshing options the mesh stage sets (0: left to Gmsh, i.e. the
/// model's own, as a .geo, -clscale or a Gmsh-API script set them).
struct MeshOptions {
  double size_min = 0;  ///< Mesh.MeshSizeMin
  double size_max = 0;  ///< Mesh.MeshSizeMax
  double factor = 0;    ///< Mesh.MeshSizeFactor
  int algorithm = 0;    ///< Mesh.Algorithm (6 = frontal-Delaunay, Gmsh's default); 0: the model's
  /// Caps on Gmsh's mesher, which runs in a child process (a size 1e9 times too
  /// small would otherwise mesh for hours): boundary lines and triangles, and
  /// wall seconds; 3/4 of the machine's memory is the third cap.
  double max_triangles = 5e7;
  double max_seconds = 600;
};

/// Gmsh's linear triangle mesh of the current model's CAD under `o` (made in
/// a child process within o's caps, then put in the model), read back.
Mesh gmsh_mesh(const std::string& input, const MeshOptions& o);

/// Gmsh's linear tetrahedral mesh of the current model's volumes (issue 24),
/// made as gmsh_mesh makes triangles, read back with its surfaces and curves.
VolumeMesh gmsh_volume_mesh(const std::string& input, const MeshOptions& o);

/// `mesh`: a new linear triangle (or, of a model with volumes, tetrahedral) mesh of the input's CAD
/// by Gmsh.
Stage mesh_stage();

}  // namespace homesh
