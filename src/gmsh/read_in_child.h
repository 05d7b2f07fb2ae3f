#pragma once
// Gmsh's `.msh` reader crashes (SIGSEGV) on some malformed files (huge tags in
// MSH 4.1, bit flips in counts), or builds a model that crashes Gmsh's API
// calls afterwards. homesh reads a `.msh` in a child process first, with every
// Gmsh call it will make on it, so that no input file can crash homesh itself:
// a crash, a runaway allocation or a hang there becomes a clear error naming
// the file, and only a file the child read to its end is read in-process.
#include <functional>
#include <string>

namespace homesh::gmsh_adapter {

/// Runs `read` (reading `path` through Gmsh) in a forked child (run_in_child), its output
/// discarded, memory capped at 1 GiB + 64 x the file's size (except under
/// AddressSanitizer, which needs its own address space) and time at 10 s +
/// 2 s per MB (Gmsh reads MSH at well over 10 MB/s; a mutated file made it
/// churn for minutes). Throws homesh::Error naming `path` if the child dies by
/// a signal, runs out of memory or time, and with the child's message if
/// `read` threw there (the file is then not read again in-process). Call before any
/// OpenMP region has run in this process (a forked child cannot use a
/// parent's OpenMP threads).
void read_in_child(const std::string& path, const std::function<void()>& read);

}  // namespace homesh::gmsh_adapter
