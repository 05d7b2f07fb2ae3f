#pragma once
// The pipeline's log: progress and reports on stdout, warnings on stderr;
// `quiet` keeps only warnings.
#include <fmt/core.h>

#include <cstdio>
#include <string>

namespace homesh {

struct Log {
  bool quiet = false;

  template <typename... Args>
  void info(fmt::format_string<Args...> f, Args&&... args) const {
    if (!quiet) fmt::print(stdout, "{}\n", fmt::format(f, std::forward<Args>(args)...));
  }
  template <typename... Args>
  void warn(fmt::format_string<Args...> f, Args&&... args) const {
    fmt::print(stderr, "homesh: warning: {}\n", fmt::format(f, std::forward<Args>(args)...));
  }
};

}  // namespace homesh
