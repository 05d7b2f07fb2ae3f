#include "core/progress.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace homesh {
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);

// The process' one progress line: the live tasks, outermost first.
struct Line {
  bool on = false;
  std::vector<const Progress*> tasks;
  Clock::time_point last_drawn;
  bool shown = false;
};

Line& line() {
  static Line l;
  return l;
}

void draw(Line& l) {
  std::string text = "homesh:";
  for (std::size_t k = 0; k < l.tasks.size(); ++k)
    text += (k == 0 ? " " : " | ") + l.tasks[k]->text();
  std::fprintf(stderr, "\r%s\033[K", text.c_str());
  std::fflush(stderr);
  l.last_drawn = Clock::now();
  l.shown = true;
}

void erase(Line& l) {
  if (!l.shown) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
  l.shown = false;
}

}  // namespace

bool progress_wanted(bool quiet) {
  if (const char* env = std::getenv("HOMESH_PROGRESS")) {
    if (std::strcmp(env, "1") == 0) return true;
    if (std::strcmp(env, "0") == 0) return false;
  }
  return !quiet && isatty(STDERR_FILENO) == 1;
}

void set_progress(bool on) {
  Line& l = line();
  if (!on) erase(l);
  l.on = on;
}

Progress::Progress(std::string label, long total) : label_(std::move(label)), total_(total) {
  Line& l = line();
  if (l.on) l.tasks.push_back(this);
}

Progress::~Progress() {
  Line& l = line();
  const auto it = std::find(l.tasks.begin(), l.tasks.end(), this);
  if (it == l.tasks.end()) return;
  l.tasks.erase(it);
  if (drawn_) erase(l);
}

void Progress::update(long done, const std::string& detail) {
  Line& l = line();
  if (!l.on) return;
  done_ = done;
  detail_ = detail;
  if (drawn_ && Clock::now() - l.last_drawn < kRedrawInterval) return;
  drawn_ = true;
  draw(l);
}

std::string Progress::text() const {
  std::string t = label_;
  if (total_ > 0) t += " " + std::to_string(done_) + "/" + std::to_string(total_);
  if (!detail_.empty()) t += " " + detail_;
  return t;
}

}  // namespace homesh
