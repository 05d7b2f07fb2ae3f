#pragma once
// The extension of a file name, as homesh picks readers and writers by it.
#include <algorithm>
#include <cctype>
#include <string>

namespace homesh {

/// The lower-case extension of `path` without its dot ("msh"), or "" if its
/// file name has none.
inline std::string file_extension(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace homesh
