#pragma once
// Test helper: run a shell command, capturing its output (stdout and stderr
// together) and exit code.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace homesh::test {

struct CommandResult {
  int exit_code = -1;
  std::string output;
};

inline CommandResult run_command(const std::string& command) {
  CommandResult r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe)) r.output += buffer.data();
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// The homesh binary with its arguments.
inline CommandResult run_homesh(const std::string& args) {
  return run_command(std::string(HOMESH_BINARY) + " " + args);
}

/// The homesh executable the CLI tests run.
inline const std::string homesh_binary = HOMESH_BINARY;

/// The project's geo/ folder (with its trailing slash), where the CLI tests
/// find their .geo inputs.
inline const std::string geo = std::string(HOMESH_SOURCE_DIR) + "/geo/";

}  // namespace homesh::test
