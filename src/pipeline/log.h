#pragma once
// The pipeline's log, the one way homesh's messages leave it: reports and
// progress notes (info), warnings, and what the user asked to see (report,
// e.g. `-m info`, shown even when quiet). By default info and reports go to
// stdout and warnings to stderr; a sink sends them elsewhere (the Python
// module: Python's `logging`, or sys.stdout/sys.stderr, so redirection and
// notebooks see them). `quiet` keeps warnings and reports; `silent` (Gmsh's
// General.Verbosity below 2) drops everything.
#include <fmt/core.h>

#include <cstdio>
#include <functional>
#include <string>

namespace homesh {

enum class LogLevel { Info, Warning };

struct Log {
  bool quiet = false;
  bool silent = false;
  /// Where messages go; empty: stdout (info) and stderr (warnings, "homesh: warning: " first).
  std::function<void(LogLevel, const std::string&)> sink;

  template <typename... Args>
  void info(fmt::format_string<Args...> f, Args&&... args) const {
    if (!quiet) emit(LogLevel::Info, fmt::format(f, std::forward<Args>(args)...));
  }
  template <typename... Args>
  void report(fmt::format_string<Args...> f, Args&&... args) const {
    if (!silent) emit(LogLevel::Info, fmt::format(f, std::forward<Args>(args)...));
  }
  template <typename... Args>
  void warn(fmt::format_string<Args...> f, Args&&... args) const {
    if (!silent) emit(LogLevel::Warning, fmt::format(f, std::forward<Args>(args)...));
  }

 private:
  void emit(LogLevel level, const std::string& text) const {
    if (sink)
      sink(level, text);
    else if (level == LogLevel::Info)
      fmt::print(stdout, "{}\n", text);
    else
      fmt::print(stderr, "homesh: warning: {}\n", text);
  }
};

}  // namespace homesh
