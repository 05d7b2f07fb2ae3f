#pragma once
// Atomic output: write to a temporary file beside the target, then rename it
// over the target in one step, so no reader ever sees a half-written file and
// a failed run leaves the previous file (if any) untouched.
#include <string>

namespace homesh {

class AtomicFile {
 public:
  /// Reserves a temporary path in the target's folder, keeping the target's
  /// extension (Gmsh picks the format from it). Throws homesh::Error naming
  /// `target` if its folder is missing or not writable.
  explicit AtomicFile(std::string target);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// The temporary path to write to.
  const std::string& temp_path() const { return temp_; }
  const std::string& target() const { return target_; }

  /// Flushes the temporary file to disk and renames it over the target.
  void commit();

  /// Removes every temporary file still pending in this process (for signal
  /// handlers: async-signal-safe, uses unlink only).
  static void remove_pending() noexcept;

 private:
  std::string target_;
  std::string temp_;
  bool committed_ = false;
};

}  // namespace homesh
