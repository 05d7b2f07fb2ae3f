#pragma once
// Gmsh ends the whole process (exit(), status 0) where a script says `Exit;`,
// even when it runs inside the API. While an ExitGuard lives, such an exit is
// turned into homesh's error naming the input and exit status 1, so a script
// that exits is never taken for a successful run.
#include <string>

namespace homesh::gmsh_adapter {

class ExitGuard {
 public:
  /// Guards the reading of `input` (its name is in the message).
  explicit ExitGuard(const std::string& input);
  ~ExitGuard();
  ExitGuard(const ExitGuard&) = delete;
  ExitGuard& operator=(const ExitGuard&) = delete;
};

}  // namespace homesh::gmsh_adapter
