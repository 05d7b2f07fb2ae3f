#include "gmsh/exit_guard.h"

#include <unistd.h>

#include <cstdlib>
#include <cstring>

namespace homesh::gmsh_adapter {
namespace {

// The message, built before the guarded call: the exit handler only writes it.
char message[4096];
bool armed = false;

extern "C" void exit_during_guard() {
  if (!armed) return;
  const ssize_t written = write(STDERR_FILENO, message, std::strlen(message));
  (void)written;
  _exit(1);
}

}  // namespace

ExitGuard::ExitGuard(const std::string& input) {
  static const bool installed = std::atexit(exit_during_guard) == 0;
  (void)installed;
  const std::string text =
      "homesh: error: " + input + ": the .geo exited (an Exit command) before a model was built\n";
  std::strncpy(message, text.c_str(), sizeof message - 1);
  message[sizeof message - 1] = '\0';
  armed = true;
}

ExitGuard::~ExitGuard() { armed = false; }

}  // namespace homesh::gmsh_adapter
