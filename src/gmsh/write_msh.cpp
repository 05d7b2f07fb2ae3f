#include "gmsh/write_msh.h"

#include <gmsh.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "gmsh/gmsh_call.h"
#include "gmsh/option_scope.h"
#include "gmsh/ungrouped_group.h"
#include "gmsh/view_style.h"

namespace homesh::gmsh_adapter {
namespace {

// Throws unless what Gmsh has written so far (`before` bytes earlier, now
// more) ends with a complete section: Gmsh ignores its own write errors, so a
// full disk or a file-size limit shows as a file cut short.
void check_section_written(const AtomicFile& file, std::uint64_t before, const std::string& what) {
  const std::uint64_t size = file.size();
  const std::string head = file.read(0, 12);
  const std::size_t tail_length = 40;
  const std::string tail = file.read(size > tail_length ? size - tail_length : 0, tail_length);
  const auto end = tail.rfind("\n$End");
  const bool whole = size > before && head == "$MeshFormat\n" && end != std::string::npos &&
                     tail.back() == '\n' && tail.find('\n', end + 1) == tail.size() - 1;
  if (!whole)
    throw Error("cannot write '" + file.target() + "': Gmsh's " + what + " is incomplete (" +
                std::to_string(size) + " bytes; is the disk full or a file size limit set?)");
}

}  // namespace

void check_msh_path(const std::string& path) {
  const std::string ext = file_extension(path);
  if (ext != "msh")
    throw Error(path + ": homesh writes .msh files only (MSH 2.2 or 4.1, as Gmsh's option " +
                "Mesh.MshFileVersion says); got '" + (ext.empty() ? "no extension" : "." + ext) +
                "'");
  AtomicFile::check_target(path);
}

void write_msh(const std::string& path, const std::vector<int>& view_tags,
               const std::string& provenance) {
  check_msh_path(path);
  double version = 4.1;
  gmsh::option::getNumber("Mesh.MshFileVersion", version);
  if (!((version >= 2 && version < 3) || (version >= 4.1 && version < 5)))
    throw Error(path + ": homesh writes MSH 2.2 or 4.1, but Gmsh's option Mesh.MshFileVersion is " +
                std::to_string(version));
  AtomicFile msh(path);
  AtomicFile opt(path + ".opt");
  std::string sidecar;
  gmsh_call("cannot write '" + path + "'", [&] {
    OptionScope options;  // the user's MshFileVersion and Binary are kept, as Gmsh's own write does
    options.set("Mesh.SaveAll", 1);
    {
      const UngroupedGroups for_meshio;
      gmsh::write(msh.temp_path());
    }
    check_section_written(msh, 0, "mesh");
    options.set("PostProcessing.SaveMesh", 0);
    for (int v : view_tags) {
      const std::uint64_t before = msh.size();
      gmsh::view::write(v, msh.temp_path(), true);
      check_section_written(msh, before, "view " + std::to_string(v));
    }
    sidecar = sidecar_options(view_tags);
  });
  msh.append("$HomeshProvenance\n" + provenance + "\n$EndHomeshProvenance\n");
  opt.append(sidecar);
  msh.commit();
  opt.commit();
}

}  // namespace homesh::gmsh_adapter
