#pragma once
// The output formats homesh writes, chosen by the output's extension: one
// table for the CLI's help, the errors and the writers' dispatch.
#include <string>
#include <vector>

namespace homesh {

enum class OutputFormat { msh, vtu };

struct OutputFormatInfo {
  OutputFormat format;
  std::string extension;  ///< without its dot, lower case
  std::string summary;
};

/// Every output format, .msh first.
const std::vector<OutputFormatInfo>& output_formats();

/// "OUTPUT.msh | OUTPUT.vtu": the formats as the CLI's usage shows them.
std::string output_formats_usage();

/// The format `path` names by its extension (any case), once checked that
/// `path` can be written (the folder exists and is writable, `path` is not a
/// folder): for checking an output before any work. Throws homesh::Error
/// naming `path` otherwise, e.g. for an unknown extension, listing the formats.
OutputFormat check_output_path(const std::string& path);

}  // namespace homesh
