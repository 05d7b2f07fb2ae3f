#pragma once
// Atomic output: write to a temporary file beside the target, then rename it
// over the target in one step, so no reader ever sees a half-written file and
// a failed run leaves the previous file (if any) untouched.
//
// The write path is checked end to end, as SQLite's and git's are: every
// write, the fsync of the file, its close, the rename and the fsync of the
// folder. Any failure throws homesh::Error naming the target and the cause
// ("No space left on device", "File too large", ...) and removes the
// temporary file. The temporary file is created here (O_EXCL) and held under
// an exclusive flock for the object's lifetime; a temporary file of the same
// target that nobody holds any more (its writer was killed, even by SIGKILL)
// is removed by the next AtomicFile of that target.
#include <cstdint>
#include <string>
#include <string_view>

namespace homesh {

class AtomicFile {
 public:
  /// Checks `target` (check_target), removes stale temporary files of it and
  /// creates the temporary file `.NAME.tmpPID.EXT` in its folder, keeping its
  /// extension (Gmsh picks the format from it). Throws homesh::Error naming
  /// `target`.
  explicit AtomicFile(std::string target);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// The temporary path to write to (another writer, e.g. Gmsh, may write it by path).
  const std::string& temp_path() const { return temp_; }
  const std::string& target() const { return target_; }

  /// Appends `data` at the end of the temporary file; every write checked.
  void append(std::string_view data);
  /// The temporary file's size in bytes.
  std::uint64_t size() const;
  /// The temporary file's bytes [offset, offset + count) (fewer at its end).
  std::string read(std::uint64_t offset, std::size_t count) const;

  /// Flushes the temporary file to disk (fsync), closes it, renames it over
  /// the target and flushes the folder. Throws homesh::Error on any failure,
  /// leaving the target as it was (unless only the folder's flush failed).
  void commit();

  /// Throws homesh::Error unless `target` can be written: its folder exists
  /// and is writable, and `target` is not a folder. For checking an output
  /// path before any work is done.
  static void check_target(const std::string& target);

  /// Removes every temporary file still pending in this process (for signal
  /// handlers: async-signal-safe, uses unlink only).
  static void remove_pending() noexcept;

 private:
  [[noreturn]] void fail(const std::string& what, int err) const;
  std::string target_;
  std::string temp_;
  int fd_ = -1;
  bool committed_ = false;
};

/// Writes `text` to `path` atomically (AtomicFile), every step checked.
void write_file_atomically(const std::string& path, std::string_view text);

}  // namespace homesh
