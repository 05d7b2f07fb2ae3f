#pragma once
// `.msh` output: the current model's mesh and the given views in one MSH
// file, the homesh command line recorded in it, and a sidecar `PATH.opt` that
// Gmsh merges when it opens PATH: the views styled as they are in this process
// (gmsh/view_style.h), so the file opens as homesh's views look here.
#include <string>
#include <vector>

namespace homesh::gmsh_adapter {

/// Writes the current model's mesh (all elements, physical groups kept) to
/// `path`, then each view of `view_tags` appended, then a `$HomeshProvenance`
/// section holding `provenance` (Gmsh skips unknown sections), in the MSH
/// version and encoding the user chose in Gmsh (Mesh.MshFileVersion 2.2 or
/// 4.1, Mesh.Binary); the Gmsh options it sets to write are restored. Both
/// `path` and `path.opt` are written atomically, each of Gmsh's sections
/// verified complete and every write, fsync, close and rename checked. Throws
/// homesh::Error naming `path` and the cause; the previous files are then
/// untouched.
void write_msh(const std::string& path, const std::vector<int>& view_tags,
               const std::string& provenance);

/// Throws homesh::Error naming `path` unless it ends in `.msh` and can be
/// written (AtomicFile::check_target): for checking an output before any work.
void check_msh_path(const std::string& path);

}  // namespace homesh::gmsh_adapter
