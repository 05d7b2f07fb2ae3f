#include "gmsh/read_in_child.h"

#include <sys/stat.h>

#include "gmsh/child_process.h"

namespace homesh::gmsh_adapter {

void read_in_child(const std::string& path, const std::function<void()>& read) {
  struct stat st {};
  const std::uint64_t size =
      stat(path.c_str(), &st) == 0 ? static_cast<std::uint64_t>(st.st_size) : 0;
  const ChildLimits limits{(std::uint64_t{1} << 30) + 64 * size,
                           std::chrono::seconds(10 + 2 * static_cast<long>(size >> 20))};
  run_in_child(limits,
               {path, "Gmsh's reader", "the file is malformed", "is a count in the file corrupt?"},
               [&](int) { read(); });
}

}  // namespace homesh::gmsh_adapter
