#pragma once
// Gmsh options set for the length of a scope: the values the user had are
// restored when it ends, so homesh never changes a user's Gmsh settings.
#include <string>
#include <utility>
#include <vector>

namespace homesh::gmsh_adapter {

class OptionScope {
 public:
  OptionScope() = default;
  OptionScope(const OptionScope&) = delete;
  OptionScope& operator=(const OptionScope&) = delete;
  /// Restores every option set through this scope, last first.
  ~OptionScope();

  /// Sets the number option `name` (e.g. "Mesh.SaveAll") to `value`.
  void set(const std::string& name, double value);

 private:
  std::vector<std::pair<std::string, double>> saved_;
};

}  // namespace homesh::gmsh_adapter
