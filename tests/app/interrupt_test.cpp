// Interrupting a run (SIGINT, SIGTERM) leaves no partial output: neither a
// half-written OUTPUT nor a temporary file beside it, nor a process of it (the
// child Gmsh meshes in) running on.
#include <dirent.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <string>
#include <thread>
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

// How many processes have `argument` among their command-line arguments.
int processes_with_argument(const std::string& argument) {
  int count = 0;
  for (const std::string& name : files_in("/proc")) {
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const std::string cmdline = homesh::test::read("/proc/" + name + "/cmdline");
    if (cmdline.find(std::string(1, '\0') + argument + '\0') != std::string::npos) ++count;
  }
  return count;
}

// Whether every process with `argument` has ended within two seconds.
bool all_ended(const std::string& argument) {
  for (int k = 0; k < 40; ++k) {
    if (processes_with_argument(argument) == 0) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
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
      // Nothing of the run goes on: not the child that meshes (4 such children
      // once burnt a core for minutes after their parents had ended).
      CHECK(all_ended(out));
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
