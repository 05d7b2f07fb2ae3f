#include "pipeline/output_format.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "gmsh/write_msh.h"

namespace homesh {

const std::vector<OutputFormatInfo>& output_formats() {
  static const std::vector<OutputFormatInfo> formats = {
      {OutputFormat::msh, "msh",
       "Gmsh MSH 4.1 (or 2.2, as Mesh.MshFileVersion says) with one view per field and an .opt "
       "sidecar"},
      {OutputFormat::vtu, "vtu",
       "VTK XML UnstructuredGrid with Lagrange cells of the mesh's order, fields as cell and "
       "point data (ParaView)"},
  };
  return formats;
}

std::string output_formats_usage() {
  std::string usage;
  for (const auto& f : output_formats())
    usage += (usage.empty() ? "" : " | ") + ("OUTPUT." + f.extension);
  return usage;
}

OutputFormat check_output_path(const std::string& path) {
  const std::string ext = file_extension(path);
  for (const auto& f : output_formats()) {
    if (f.extension != ext) continue;
    if (f.format == OutputFormat::msh)
      gmsh_adapter::check_msh_path(path);
    else
      AtomicFile::check_target(path);
    return f.format;
  }
  std::string known;
  for (const auto& f : output_formats()) known += (known.empty() ? "." : " or .") + f.extension;
  throw Error(path +
              (ext.empty() ? ": no extension to choose the output format by"
                           : ": unknown output format '." + ext + "'") +
              " (homesh writes " + known + ")");
}

}  // namespace homesh
