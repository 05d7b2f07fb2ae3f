#include "core/atomic_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
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

struct PathParts {
  std::string folder;  // "." when the path has no slash
  std::string prefix;  // what goes before a file name in that folder ("" or "folder/")
  std::string base;    // the file name
  std::string ext;     // ".msh", or "" without a dot
};

PathParts split(const std::string& path) {
  PathParts p;
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) {
    p.folder = ".";
    p.base = path;
  } else {
    p.folder = slash == 0 ? "/" : path.substr(0, slash);
    p.prefix = path.substr(0, slash + 1);
    p.base = path.substr(slash + 1);
  }
  const auto dot = p.base.find_last_of('.');
  p.ext = dot == std::string::npos || dot == 0 ? "" : p.base.substr(dot);
  return p;
}

std::string message(const std::string& target, const std::string& what, int err) {
  return "cannot write '" + target + "': " + what +
         (err ? ": " + std::string(std::strerror(err)) : "");
}

// The writer's process id in a temporary file name `.BASE.tmpPID[_N]EXT`, or
// -1 if `name` is not one of `p`'s.
long temp_owner(const std::string& name, const PathParts& p) {
  const std::string head = "." + p.base + ".tmp";
  if (name.size() <= head.size() + p.ext.size() || name.compare(0, head.size(), head) != 0 ||
      name.compare(name.size() - p.ext.size(), p.ext.size(), p.ext) != 0)
    return -1;
  const std::string middle = name.substr(head.size(), name.size() - head.size() - p.ext.size());
  const auto underscore = middle.find('_');
  const std::string pid = middle.substr(0, underscore);
  if (pid.empty() || pid.size() > 9 || pid.find_first_not_of("0123456789") != std::string::npos)
    return -1;
  if (underscore != std::string::npos &&
      (underscore + 1 == middle.size() ||
       middle.find_first_not_of("0123456789", underscore + 1) != std::string::npos))
    return -1;
  return std::stol(pid);
}

// Removes the temporary files of `p` that no live writer holds: a writer
// holds its file's flock until it renames or removes it, so a file whose lock
// can be taken and whose writer's process is gone (or is this one) is stale.
void remove_stale(const PathParts& p) {
  DIR* dir = opendir(p.folder.c_str());
  if (!dir) return;
  while (const dirent* entry = readdir(dir)) {
    const std::string name = entry->d_name;
    const long pid = temp_owner(name, p);
    if (pid < 0) continue;
    const bool gone = pid == getpid() || (kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH);
    if (!gone) continue;
    const std::string path = p.prefix + name;
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
    if (fd < 0) continue;
    if (flock(fd, LOCK_EX | LOCK_NB) == 0) unlink(path.c_str());
    close(fd);
  }
  closedir(dir);
}

}  // namespace

void AtomicFile::check_target(const std::string& target) {
  const PathParts p = split(target);
  if (p.base.empty()) throw Error(message(target, "it names a folder, not a file", 0));
  struct stat st {};
  if (stat(p.folder.c_str(), &st) != 0)
    throw Error(message(target, "folder '" + p.folder + "'", errno));
  if (!S_ISDIR(st.st_mode)) throw Error(message(target, "'" + p.folder + "' is not a folder", 0));
  if (access(p.folder.c_str(), W_OK | X_OK) != 0)
    throw Error(message(target, "folder '" + p.folder + "'", errno));
  if (stat(target.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw Error(message(target, "it is a folder", 0));
}

AtomicFile::AtomicFile(std::string target) : target_(std::move(target)) {
  check_target(target_);
  const PathParts p = split(target_);
  remove_stale(p);
  struct stat old {};
  const bool replaces = stat(target_.c_str(), &old) == 0;
  for (int n = 0; fd_ < 0; ++n) {
    temp_ = p.prefix + "." + p.base + ".tmp" + std::to_string(getpid()) +
            (n ? "_" + std::to_string(n) : "") + p.ext;
    fd_ = open(temp_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ < 0 && (errno != EEXIST || n == 99)) fail("cannot create '" + temp_ + "'", errno);
  }
  add_pending(temp_.c_str());
  // The new file keeps the permissions of the one it replaces.
  const char* failed = flock(fd_, LOCK_EX) != 0 ? "lock"
                       : replaces && fchmod(fd_, old.st_mode & 07777) != 0
                           ? "set the permissions of"
                           : nullptr;
  if (failed) {
    const int err = errno;
    unlink(temp_.c_str());
    drop_pending(temp_.c_str());
    close(fd_);
    fail(std::string("cannot ") + failed + " '" + temp_ + "'", err);
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) unlink(temp_.c_str());
  drop_pending(temp_.c_str());
  if (fd_ >= 0) close(fd_);
}

void AtomicFile::fail(const std::string& what, int err) const {
  throw Error(message(target_, what, err));
}

void AtomicFile::append(std::string_view data) {
  if (lseek(fd_, 0, SEEK_END) < 0) fail("cannot seek '" + temp_ + "'", errno);
  while (!data.empty()) {
    const ssize_t n = write(fd_, data.data(), data.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("write failed", n < 0 ? errno : EIO);
    data.remove_prefix(static_cast<std::size_t>(n));
  }
}

std::uint64_t AtomicFile::size() const {
  struct stat st {};
  if (fstat(fd_, &st) != 0) fail("cannot stat '" + temp_ + "'", errno);
  return static_cast<std::uint64_t>(st.st_size);
}

std::string AtomicFile::read(std::uint64_t offset, std::size_t count) const {
  std::string out(count, '\0');
  std::size_t got = 0;
  while (got < count) {
    const ssize_t n = pread(fd_, out.data() + got, count - got, static_cast<off_t>(offset + got));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail("cannot read back '" + temp_ + "'", errno);
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  out.resize(got);
  return out;
}

void AtomicFile::commit() {
  if (fsync(fd_) != 0) fail("fsync failed", errno);
  const int fd = fd_;
  fd_ = -1;
  if (close(fd) != 0) fail("close failed", errno);
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) fail("rename failed", errno);
  committed_ = true;
  // The rename itself reaches the disk with the folder's fsync (EINVAL: a file
  // system that cannot sync folders, where there is nothing more to do).
  const PathParts p = split(target_);
  const int dir = open(p.folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) fail("cannot open its folder to sync it", errno);
  const int synced = fsync(dir) == 0 || errno == EINVAL ? 0 : errno;
  close(dir);
  if (synced) fail("written, but its folder's fsync failed", synced);
}

void AtomicFile::remove_pending() noexcept {
  for (auto& slot : pending) {
    const char* path = slot.load();
    if (path) unlink(path);
  }
}

void write_file_atomically(const std::string& path, std::string_view text) {
  AtomicFile file(path);
  file.append(text);
  file.commit();
}

}  // namespace homesh
