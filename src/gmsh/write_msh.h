#pragma once
// `.msh` output: the current model's mesh and the given views in one MSH 4.1
// file, the homesh command line recorded in it, and a sidecar `PATH.opt` that
// Gmsh merges when it opens PATH, so curved fields display curved.
#include <string>
#include <vector>

namespace homesh::gmsh_adapter {

/// Writes the current model's mesh (all elements, physical groups kept) to
/// `path`, then each view of `view_tags` appended, then a `$HomeshProvenance`
/// section holding `provenance` (Gmsh skips unknown sections). Both `path` and
/// `path.opt` are written atomically. Throws homesh::Error naming `path`.
void write_msh(const std::string& path, const std::vector<int>& view_tags,
               const std::string& provenance);

/// The sidecar options text for a file holding `num_views` views.
std::string sidecar_options(int num_views);

}  // namespace homesh::gmsh_adapter
