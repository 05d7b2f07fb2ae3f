#include "study/study_output.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "core/atomic_file.h"
#include "core/error.h"

namespace homesh {

StudyOutput::StudyOutput(std::string folder) : folder_(std::move(folder)) {
  std::error_code ec;
  std::filesystem::create_directories(folder_, ec);
  if (ec) throw Error("cannot create output folder " + folder_ + ": " + ec.message());
}

std::string StudyOutput::path(const std::string& name) const { return folder_ + "/" + name; }

void StudyOutput::write(const std::string& name, const std::string& text) const {
  write_file_atomically(path(name), text);
}

std::string number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return fmt::format("{:.6g}", value);
}

}  // namespace homesh
