#pragma once
// Progress of long runs (rotation sweeps, curving large meshes, crystal
// growth) on a terminal: one line on stderr, "homesh: stage 2/3 rotate |
// step 45/360 45 deg", redrawn in place (\r) at most every 0.1 s and erased
// when the task ends. Off unless the entry point (CLI, Python module, C++ API)
// turns it on, so library code and tests stay quiet; when off, a task costs a
// flag test per update.
//
//   Progress task("step", max_steps);      // in a loop of known length
//   for (int k = 1; ...; ++k) task.update(k, std::to_string(angle) + " deg");
//
// Tasks nest: each part of the line is one live task or label, outermost
// first. Not thread-safe by design: update from the thread that runs the loop.
#include <string>

namespace homesh {

/// Whether an entry point should draw progress: HOMESH_PROGRESS=1 or 0 if that
/// variable is set (for tests and pipes), otherwise when stderr is a terminal
/// and the run is not quiet. The one place homesh reads the environment.
bool progress_wanted(bool quiet);

/// Turns drawing on or off for the whole process (off at start).
void set_progress(bool on);

/// One task of `total` units, shown as "label done/total detail". A task
/// never updated draws nothing: it only labels the tasks inside its scope
/// (e.g. "stage 2/3 rotate"), so a stage's own report is never mixed with a
/// progress line.
class Progress {
 public:
  Progress(std::string label, long total);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// `done` units of `total` finished; `detail` e.g. the current angle. The
  /// first update draws at once, later ones when 0.1 s have passed since the
  /// last drawing.
  void update(long done, const std::string& detail = "");

  /// "label done/total detail" as drawn ("label detail" if total <= 0).
  std::string text() const;

 private:
  std::string label_;
  long total_;
  long done_ = 0;
  std::string detail_;
  bool drawn_ = false;
};

}  // namespace homesh
