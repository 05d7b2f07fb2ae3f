#pragma once
// Runs a piece of Gmsh work in a forked child process, capped in memory and
// time, so that a crash, a runaway allocation or a hang inside Gmsh becomes a
// clear homesh::Error instead of killing or freezing homesh. The child can send
// bytes back (a mesh, say) through a pipe the parent drains as they come.
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>

namespace homesh::gmsh_adapter {

struct ChildLimits {
  /// Address-space cap of the child (RLIMIT_AS), bytes; 0 = none. Not applied
  /// under AddressSanitizer, which needs its own address space.
  std::uint64_t memory = 0;
  /// Wall-time cap; the child is killed when it is reached.
  std::chrono::seconds time{0};
};

/// How the errors of run_in_child read: "<subject>: <doer> crashed on it
/// (Segmentation fault): <crash_hint>", "... needs more than N MB ...: <limit_hint>".
struct ChildWording {
  std::string subject;     ///< what the error names first: the input file, the model
  std::string doer;        ///< "Gmsh's reader", "Gmsh's mesher"
  std::string crash_hint;  ///< after a crash or an unexpected exit
  std::string limit_hint;  ///< after running out of memory or time
};

/// Runs `work(fd)` in a forked child with its stdout and stderr discarded and
/// the default crash handlers; `work` may write bytes to `fd`, and returns them
/// all. Throws homesh::Error worded by `wording` if the child dies by a signal,
/// runs out of memory (std::bad_alloc) or time, exits otherwise than by
/// returning from `work`, or if `work` threw (with its message, prefixed by the
/// subject unless it names it). Call before any OpenMP region has run in this
/// process, or with Gmsh's threads at 1 (a forked child cannot use a parent's
/// OpenMP threads).
std::string run_in_child(const ChildLimits& limits, const ChildWording& wording,
                         const std::function<void(int fd)>& work);

}  // namespace homesh::gmsh_adapter
