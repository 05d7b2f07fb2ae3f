// Interrupting a run (SIGINT, SIGTERM) leaves no partial output: neither a
// half-written OUTPUT nor a temporary file beside it.
#include <dirent.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "../support/temp_dir.h"

namespace {

std::vector<std::string> files_in(const std::string& dir) {
  std::vector<std::string> names;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d))
      if (std::string(e->d_name) != "." && std::string(e->d_name) != "..")
        names.push_back(e->d_name);
    closedir(d);
  }
  return names;
}

}  // namespace

TEST_CASE("SIGINT or SIGTERM at any moment leaves no partial output", "[app]") {
  const std::string input = std::string(HOMESH_SOURCE_DIR) + "/geo/naca.geo";
  int interrupted = 0;
  for (int signal_number : {SIGINT, SIGTERM}) {
    for (int delay_ms : {300, 900, 1500, 2100}) {
      CAPTURE(signal_number, delay_ms);
      const homesh::test::TempDir dir;
      const std::string out = dir / "out.msh";
      const pid_t pid = fork();
      REQUIRE(pid >= 0);
      if (pid == 0) {
        freopen("/dev/null", "w", stdout);
        execl(HOMESH_BINARY, HOMESH_BINARY, input.c_str(), "-m", "mesh:size_max=0.01", "-m",
              "curve:p=4", "-m", "quality", out.c_str(), static_cast<char*>(nullptr));
        _exit(127);
      }
      usleep(delay_ms * 1000);
      kill(pid, signal_number);
      int status = 0;
      waitpid(pid, &status, 0);
      const auto files = files_in(dir.path());
      if (WIFSIGNALED(status)) {  // killed before main() installed its handlers
        REQUIRE(files.empty());
        continue;
      }
      REQUIRE(WIFEXITED(status));
      const int code = WEXITSTATUS(status);
      if (code == 0) {  // finished before the signal: complete output only
        REQUIRE(files.size() == 2);
      } else {
        ++interrupted;
        REQUIRE(code == 128 + signal_number);
        INFO("left behind: " << (files.empty() ? "" : files[0]));
        REQUIRE(files.empty());
      }
    }
  }
  REQUIRE(interrupted > 0);
}
