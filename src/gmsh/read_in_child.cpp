#include "gmsh/read_in_child.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <new>
#include <string>
#include <thread>

#include "core/error.h"

#if defined(__SANITIZE_ADDRESS__)
#define HOMESH_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HOMESH_ASAN 1
#endif
#endif

namespace homesh::gmsh_adapter {
namespace {

constexpr int kOutOfMemory = 3;
constexpr int kFailed = 4;

[[noreturn]] void child(const std::function<void()>& read, std::uint64_t memory, int report) {
  // A crash here must reach the parent as a signal, not through a handler the
  // process installed (libFuzzer's writes a crash file and exits with a code).
  for (int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL}) std::signal(sig, SIG_DFL);
  const int null = open("/dev/null", O_WRONLY);
  if (null >= 0) {  // the parent reports; Gmsh's messages would come twice
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
  }
#ifndef HOMESH_ASAN
  const rlimit cap{memory, memory};
  setrlimit(RLIMIT_AS, &cap);
#else
  (void)memory;
#endif
  int code = 0;
  std::string message;
  try {
    read();
  } catch (const std::bad_alloc&) {
    code = kOutOfMemory;
  } catch (const std::exception& e) {
    code = kFailed;
    message = e.what();
  } catch (...) {
    code = kFailed;
  }
  // The reason goes to the parent, which then need not read the file again
  // (without the memory cap, a mutated count made Gmsh churn for minutes).
  message.resize(std::min<std::size_t>(message.size(), 4000));
  const ssize_t written = write(report, message.data(), message.size());
  (void)written;
  _exit(code);
}

}  // namespace

void read_in_child(const std::string& path, const std::function<void()>& read) {
  struct stat st {};
  const std::uint64_t size =
      stat(path.c_str(), &st) == 0 ? static_cast<std::uint64_t>(st.st_size) : 0;
  const std::uint64_t memory = (std::uint64_t{1} << 30) + 64 * size;
  const auto limit = std::chrono::seconds(10 + 2 * static_cast<long>(size >> 20));

  int report[2];
  if (pipe(report) != 0)
    throw Error(path + ": cannot check it in a child process: " + std::strerror(errno));
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t pid = fork();
  if (pid < 0) {
    close(report[0]);
    close(report[1]);
    throw Error(path + ": cannot check it in a child process: " + std::strerror(errno));
  }
  if (pid == 0) {
    close(report[0]);
    child(read, memory, report[1]);
  }
  close(report[1]);
  std::string reason;
  const auto collect = [&] {  // at most 4000 bytes: the pipe never fills
    char buf[4096];
    for (ssize_t n; (n = ::read(report[0], buf, sizeof buf)) > 0;)
      reason.append(buf, static_cast<std::size_t>(n));
    close(report[0]);
  };

  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  for (auto pause = std::chrono::microseconds(200);;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR)
      throw Error(path + ": lost its reader: " + std::strerror(errno));
    if (std::chrono::steady_clock::now() - start > limit) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      close(report[0]);
      throw Error(path + ": Gmsh's reader did not finish within " + std::to_string(limit.count()) +
                  " s: is a count in the file corrupt?");
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }
  collect();
  if (WIFSIGNALED(status))
    throw Error(path + ": Gmsh's reader crashed on it (" + strsignal(WTERMSIG(status)) +
                "): the file is malformed");
  if (WIFEXITED(status) && WEXITSTATUS(status) == kOutOfMemory)
    throw Error(path + ": Gmsh's reader needs more than " + std::to_string(memory >> 20) +
                " MB for it: is a count in the file corrupt?");
  if (WIFEXITED(status) && WEXITSTATUS(status) == kFailed)
    throw Error(reason.find(path) == std::string::npos ? path + ": " + reason : reason);
  if (!WIFEXITED(status) ||
      WEXITSTATUS(status) != 0)  // e.g. Gmsh called exit(): not read to its end
    throw Error(path + ": Gmsh's reader ended with status " +
                std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                ": the file is malformed");
}

}  // namespace homesh::gmsh_adapter
