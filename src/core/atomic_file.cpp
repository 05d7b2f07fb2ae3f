#include "core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/error.h"

namespace homesh {
namespace {

// Pending temporary paths, fixed-size so a signal handler can walk them.
constexpr int kMaxPending = 64;
std::array<std::atomic<const char*>, kMaxPending> pending{};

void add_pending(const char* path) {
  for (auto& slot : pending) {
    const char* expected = nullptr;
    if (slot.compare_exchange_strong(expected, path)) return;
  }
}

void drop_pending(const char* path) {
  for (auto& slot : pending) {
    const char* expected = path;
    if (slot.compare_exchange_strong(expected, nullptr)) return;
  }
}

std::string folder_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
}

}  // namespace

AtomicFile::AtomicFile(std::string target) : target_(std::move(target)) {
  const std::string folder = folder_of(target_);
  if (access(folder.c_str(), W_OK) != 0)
    throw Error("cannot write '" + target_ + "': folder '" + folder + "' " +
                std::strerror(errno));
  const auto slash = target_.find_last_of('/');
  const std::string base = slash == std::string::npos ? target_ : target_.substr(slash + 1);
  const auto dot = base.find_last_of('.');
  const std::string ext = dot == std::string::npos ? "" : base.substr(dot);
  temp_ = (folder == "." && slash == std::string::npos ? "" : folder + "/") + "." + base +
          ".tmp" + std::to_string(getpid()) + ext;
  add_pending(temp_.c_str());
}

AtomicFile::~AtomicFile() {
  drop_pending(temp_.c_str());
  if (!committed_) std::remove(temp_.c_str());
}

void AtomicFile::commit() {
  const int fd = open(temp_.c_str(), O_RDONLY);
  if (fd < 0) throw Error("cannot write '" + target_ + "': nothing was written");
  fsync(fd);
  close(fd);
  if (std::rename(temp_.c_str(), target_.c_str()) != 0)
    throw Error("cannot write '" + target_ + "': " + std::strerror(errno));
  committed_ = true;
}

void AtomicFile::remove_pending() noexcept {
  for (auto& slot : pending) {
    const char* path = slot.load();
    if (path) unlink(path);
  }
}

}  // namespace homesh
