#include "gmsh/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <new>
#include <string>

#include "core/error.h"
#include "core/sanitizers.h"

#if defined(HOMESH_ASAN)
#include <sanitizer/common_interface_defs.h>
#endif

namespace homesh::gmsh_adapter {
namespace {

constexpr int kOutOfMemory = 3;
constexpr int kFailed = 4;
constexpr std::size_t kMaxReason = 4000;  // below a pipe's buffer: the report never blocks

[[noreturn]] void child(const std::function<void(int)>& work, const ChildLimits& limits, int data,
                        int report, pid_t parent) {
  // The child ends with its parent: a homesh ended by SIGTERM or SIGINT (or
  // killed) must not leave Gmsh meshing on, unseen, for minutes. The parent may
  // have gone before the request: then getppid() is no longer it.
  if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent) _exit(kFailed);
  // A crash here must reach the parent as a signal, not through a handler the
  // process installed (libFuzzer's writes a crash file and exits with a code).
  for (int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL}) std::signal(sig, SIG_DFL);
#if defined(HOMESH_ASAN)
  // Nor through a sanitizer's death callback: libFuzzer's writes the parent's
  // input as a crash-* file when ASan refuses Gmsh a corrupt count's allocation.
  __sanitizer_set_death_callback(nullptr);
#endif
  std::signal(SIGPIPE, SIG_DFL);  // a parent gone or done: end quietly
  const int null = open("/dev/null", O_WRONLY);
  if (null >= 0) {  // the parent reports; Gmsh's messages would come twice
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
  }
#ifndef HOMESH_ASAN
  if (limits.memory > 0) {
    const rlimit cap{limits.memory, limits.memory};
    setrlimit(RLIMIT_AS, &cap);
  }
#else
  (void)limits;
#endif
  int code = 0;
  std::string message;
  try {
    work(data);
  } catch (const std::bad_alloc&) {
    code = kOutOfMemory;
  } catch (const std::exception& e) {
    code = kFailed;
    message = e.what();
  } catch (...) {
    code = kFailed;
  }
  message.resize(std::min(message.size(), kMaxReason));
  const ssize_t written = write(report, message.data(), message.size());
  (void)written;
  _exit(code);
}

std::string failure(const ChildWording& w, const std::string& what, const std::string& hint) {
  return w.subject + ": " + w.doer + " " + what + (hint.empty() ? "" : ": " + hint);
}

// Reads `fd` into `out` until end of file or `deadline`; false on the deadline.
bool drain(int fd, std::string& out, std::chrono::steady_clock::time_point deadline) {
  char buf[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) return true;  // treated as the end: the exit status tells
    if (ready <= 0) continue;
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n > 0) {
      out.append(buf, static_cast<std::size_t>(n));
    } else if (n == 0 || errno != EINTR) {
      return true;
    }
  }
}

}  // namespace

std::string run_in_child(const ChildLimits& limits, const ChildWording& wording,
                         const std::function<void(int fd)>& work) {
  int data[2], report[2];
  if (pipe(data) != 0)
    throw Error(wording.subject + ": cannot start a child process: " + std::strerror(errno));
  if (pipe(report) != 0) {
    close(data[0]);
    close(data[1]);
    throw Error(wording.subject + ": cannot start a child process: " + std::strerror(errno));
  }
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    for (int fd : {data[0], data[1], report[0], report[1]}) close(fd);
    throw Error(wording.subject + ": cannot start a child process: " + std::strerror(errno));
  }
  if (pid == 0) {
    close(data[0]);
    close(report[0]);
    child(work, limits, data[1], report[1], parent);
  }
  close(data[1]);
  close(report[1]);

  const auto deadline = std::chrono::steady_clock::now() + limits.time;
  std::string bytes;
  const bool in_time = drain(data[0], bytes, deadline);
  close(data[0]);
  int status = 0;
  bool killed = !in_time;
  if (in_time) {  // the data pipe is closed: the child is ending, but give it the same deadline
    for (auto pause = std::chrono::microseconds(200);;) {
      const pid_t done = waitpid(pid, &status, WNOHANG);
      if (done == pid) break;
      if (done < 0 && errno != EINTR) {
        close(report[0]);
        throw Error(wording.subject + ": lost its child process: " + std::strerror(errno));
      }
      if (std::chrono::steady_clock::now() > deadline) {
        killed = true;
        break;
      }
      usleep(static_cast<useconds_t>(pause.count()));
      pause = std::min(pause * 2, std::chrono::microseconds(20000));
    }
  }
  if (killed) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    close(report[0]);
    throw Error(failure(wording,
                        "did not finish within " + std::to_string(limits.time.count()) + " s",
                        wording.limit_hint));
  }
  std::string reason;
  char buf[kMaxReason + 96];
  for (ssize_t n; (n = ::read(report[0], buf, sizeof buf)) > 0;)
    reason.append(buf, static_cast<std::size_t>(n));
  close(report[0]);

  if (WIFSIGNALED(status))
    throw Error(failure(wording, std::string("crashed on it (") + strsignal(WTERMSIG(status)) + ")",
                        wording.crash_hint));
  if (WIFEXITED(status) && WEXITSTATUS(status) == kOutOfMemory)
    throw Error(failure(wording, "needs more than " + std::to_string(limits.memory >> 20) + " MB",
                        wording.limit_hint));
  if (WIFEXITED(status) && WEXITSTATUS(status) == kFailed)
    throw Error(reason.find(wording.subject) == std::string::npos ? wording.subject + ": " + reason
                                                                  : reason);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)  // e.g. Gmsh called exit()
    throw Error(
        failure(wording,
                "ended with status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1),
                wording.crash_hint));
  return bytes;
}

}  // namespace homesh::gmsh_adapter
