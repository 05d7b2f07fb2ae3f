#pragma once
// The commands of a Gmsh `.geo` script that reach outside the model: run a
// program (System, SystemCall, NonBlockingSystemCall, OnelabRun), write or
// create files (Save, Print, CreateDir, CreateFolder) or stall (Sleep).
// homesh scans a `.geo` and the files it includes before Gmsh parses it, so
// an untrusted script cannot run a command behind the user's back. (`Exit`,
// which ends the process, may stand in a branch never taken: it is caught
// when it runs, by gmsh/exit_guard.h.)
#include <string>
#include <vector>

namespace homesh::gmsh_adapter {

struct GeoCommand {
  std::string file;  ///< the script it stands in (the input or an included file)
  int line = 0;      ///< 1-based
  std::string name;  ///< "System", "Save", ... or "Include"/"Merge" (of a computed path)
};

/// The outside-reaching commands of the `.geo` text `text` (read from `file`),
/// and of the `.geo` files it includes or merges by a literal path (relative
/// to `file`'s folder), in order of appearance. Comments and strings are
/// skipped; a command counts where a statement starts (an identifier named
/// like a command but assigned, `Save = 1;`, does not). An Include or Merge of
/// a path computed at run time, which cannot be scanned, is listed as
/// "Include" or "Merge".
std::vector<GeoCommand> geo_commands(const std::string& file, const std::string& text);

/// The same for the file `path` (read here). Throws homesh::Error if it cannot be read.
std::vector<GeoCommand> geo_file_commands(const std::string& path);

}  // namespace homesh::gmsh_adapter
