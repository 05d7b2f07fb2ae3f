// AtomicFile: the write path checked end to end. A failed write (file-size
// limit, full disk) throws an error naming the target and the cause, leaves
// the previous file intact and no temporary file behind; a temporary file
// whose writer was killed is removed by the next writer of that target.
#include "core/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "../support/temp_dir.h"
#include "core/error.h"

namespace fs = std::filesystem;
using homesh::AtomicFile;

namespace {

using homesh::test::read;

void write_plain(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// The files of `dir` other than `keep`: what a writer left behind.
std::vector<std::string> others(const std::string& dir, const std::string& keep) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename() != keep) out.push_back(e.path().filename().string());
  return out;
}

// A process id no process has now.
pid_t dead_pid() {
  pid_t pid = 4000000;
  while (kill(pid, 0) == 0 || errno != ESRCH) --pid;
  return pid;
}

// Runs `body` in a child process under a file-size limit of `bytes`, SIGXFSZ
// ignored as homesh's CLI does; returns what the child wrote on its pipe.
template <typename Body>
std::string in_child_with_size_limit(rlim_t bytes, Body body) {
  int fds[2];
  REQUIRE(pipe(fds) == 0);
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    close(fds[0]);
    signal(SIGXFSZ, SIG_IGN);
    const rlimit cap{bytes, bytes};
    setrlimit(RLIMIT_FSIZE, &cap);
    std::string said;
    try {
      body();
      said = "no error";
    } catch (const homesh::Error& e) {
      said = e.what();
    }
    const ssize_t n = ::write(fds[1], said.data(), said.size());
    _exit(n < 0);
  }
  close(fds[1]);
  std::string said;
  char buf[512];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;)
    said.append(buf, static_cast<std::size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  REQUIRE(WIFEXITED(status));
  return said;
}

}  // namespace

TEST_CASE("AtomicFile replaces the target at commit and only then", "[core][atomic_file]") {
  const homesh::test::TempDir dir;
  const std::string target = dir.path() + "/out.msh";
  write_plain(target, "old");
  {
    AtomicFile f(target);
    f.append("new ");
    f.append("contents");
    REQUIRE(read(target) == "old");
    REQUIRE(f.size() == 12);
    REQUIRE(f.read(4, 100) == "contents");
    f.commit();
  }
  REQUIRE(read(target) == "new contents");
  REQUIRE(others(dir.path(), "out.msh").empty());
  {
    AtomicFile f(target);
    f.append("abandoned");
  }
  REQUIRE(read(target) == "new contents");
  REQUIRE(others(dir.path(), "out.msh").empty());
}

TEST_CASE("AtomicFile keeps the permissions of the file it replaces", "[core][atomic_file]") {
  const homesh::test::TempDir dir;
  const std::string target = dir.path() + "/out.msh";
  write_plain(target, "old");
  fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  homesh::write_file_atomically(target, "new");
  REQUIRE((fs::status(target).permissions() & fs::perms::all) ==
          (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
}

TEST_CASE("AtomicFile::check_target refuses a missing folder and a folder as target",
          "[core][atomic_file]") {
  const homesh::test::TempDir dir;
  REQUIRE_THROWS_WITH(AtomicFile::check_target(dir.path() + "/nosuch/out.msh"),
                      Catch::Contains("nosuch") && Catch::Contains("No such file or directory"));
  fs::create_directory(dir.path() + "/sub.msh");
  REQUIRE_THROWS_WITH(AtomicFile::check_target(dir.path() + "/sub.msh"),
                      Catch::Contains("is a folder"));
  REQUIRE_THROWS_WITH(AtomicFile(dir.path() + "/"), Catch::Contains("names a folder"));
  REQUIRE_NOTHROW(AtomicFile::check_target(dir.path() + "/fine.msh"));
}

TEST_CASE("A write past the file-size limit fails naming the cause and the old file stays",
          "[core][atomic_file]") {
  const homesh::test::TempDir dir;
  const std::string target = dir.path() + "/out.msh";
  write_plain(target, "the user's good file");
  const std::string said = in_child_with_size_limit(4096, [&] {
    AtomicFile f(target);
    f.append(std::string(100000, 'x'));
    f.commit();
  });
  REQUIRE_THAT(
      said, Catch::Contains("cannot write '" + target + "'") && Catch::Contains("File too large"));
  REQUIRE(read(target) == "the user's good file");
  REQUIRE(others(dir.path(), "out.msh").empty());
}

TEST_CASE("A full disk fails the write with ENOSPC and the old file stays", "[core][atomic_file]") {
  const homesh::test::TempDir dir;
  const std::string mnt = dir.path() + "/small";
  fs::create_directory(mnt);
  // A 64 KiB tmpfs needs root (as CI runs); elsewhere the file-size test above covers the path.
  if (geteuid() != 0 || mount("tmpfs", mnt.c_str(), "tmpfs", 0, "size=64k") != 0) {
    WARN("not root or no tmpfs: the full-disk case is not run here");
    return;
  }
  const std::string target = mnt + "/out.msh";
  write_plain(target, "the user's good file");
  std::string said;
  try {
    AtomicFile f(target);
    f.append(std::string(1 << 20, 'x'));
    f.commit();
  } catch (const homesh::Error& e) {
    said = e.what();
  }
  const std::string left = read(target);
  const auto rest = others(mnt, "out.msh");
  umount(mnt.c_str());
  REQUIRE_THAT(said, Catch::Contains("No space left on device"));
  REQUIRE(left == "the user's good file");
  REQUIRE(rest.empty());
}

TEST_CASE("A temporary file whose writer died is removed by the next writer, a live one is kept",
          "[core][atomic_file]") {
  const homesh::test::TempDir dir;
  const std::string target = dir.path() + "/out.msh";
  const std::string stale = dir.path() + "/.out.msh.tmp" + std::to_string(dead_pid()) + ".msh";
  const std::string unrelated = dir.path() + "/.out.msh.tmpabc.msh";
  write_plain(stale, "left by a kill -9");
  write_plain(unrelated, "not homesh's naming");
  {
    AtomicFile held(target);  // a live writer of the same target, in this process
    AtomicFile other(target);
    REQUIRE(other.temp_path() != held.temp_path());
    REQUIRE(fs::exists(held.temp_path()));
  }
  REQUIRE_FALSE(fs::exists(stale));
  REQUIRE(fs::exists(unrelated));

  // A writer killed by SIGKILL, mid-write.
  int ready[2];
  REQUIRE(pipe(ready) == 0);
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    AtomicFile f(target);
    f.append("half a mesh");
    const ssize_t n = ::write(ready[1], "1", 1);
    (void)n;
    pause();
    _exit(0);
  }
  char c;
  REQUIRE(::read(ready[0], &c, 1) == 1);
  const std::string killed = dir.path() + "/.out.msh.tmp" + std::to_string(pid) + ".msh";
  REQUIRE(fs::exists(killed));
  homesh::write_file_atomically(target, "while the other is alive");
  REQUIRE(fs::exists(killed));  // its writer still holds it
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  homesh::write_file_atomically(target, "after the kill");
  REQUIRE_FALSE(fs::exists(killed));
  REQUIRE(read(target) == "after the kill");
}
