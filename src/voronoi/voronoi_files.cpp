#include "voronoi/voronoi_files.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace homesh {
namespace {

// The data lines of a text file: (1-based line number, text), blank and
// '#' lines dropped.
std::vector<std::pair<int, std::string>> data_lines(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot be read");
  std::vector<std::pair<int, std::string>> out;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    out.emplace_back(n, line);
  }
  return out;
}

// Exactly `count` finite numbers after `skip` leading words, or an error.
std::vector<double> numbers(const std::string& path, int line, const std::string& text, int count,
                            const std::string& what, int skip = 0) {
  std::istringstream in(text);
  std::string word;
  for (int k = 0; k < skip; ++k) in >> word;
  std::vector<double> v;
  while (in >> word) {
    char* end = nullptr;
    const double x = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0' || !std::isfinite(x))
      throw Error(path + ":" + std::to_string(line) + ": '" + word + "' is not a finite number (" +
                  what + ")");
    v.push_back(x);
  }
  if (static_cast<int>(v.size()) != count)
    throw Error(path + ":" + std::to_string(line) + ": expected " + what + ", found " +
                std::to_string(v.size()) + " numbers");
  return v;
}

}  // namespace

SeedList read_seed_file(const std::string& path) {
  const auto lines = data_lines(path);
  if (lines.empty()) throw Error(path + ": holds no seed (one 'x y' per line)");
  SeedList out;
  out.points.resize(2, static_cast<Eigen::Index>(lines.size()));
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const auto v = numbers(path, lines[k].first, lines[k].second, 2, "'x y'");
    out.points.col(k) << v[0], v[1];
    out.lines.push_back(lines[k].first);
  }
  return out;
}

MetricField read_metric_file(const std::string& path) {
  const auto lines = data_lines(path);
  if (lines.empty() || lines[0].second.find("grid") != lines[0].second.find_first_not_of(" \t"))
    throw Error(path + ":" + std::to_string(lines.empty() ? 1 : lines[0].first) +
                ": expected the header 'grid NX NY XMIN YMIN XMAX YMAX'");
  const int header = lines[0].first;
  const auto h = numbers(path, header, lines[0].second, 6, "'grid NX NY XMIN YMIN XMAX YMAX'", 1);
  // Range first: converting a double beyond int's range is undefined behaviour.
  constexpr double kMaxNodesPerSide = 1e7;
  auto count_ok = [&](double v) { return v >= 2 && v <= kMaxNodesPerSide && v == std::floor(v); };
  if (!count_ok(h[0]) || !count_ok(h[1]) || !(h[4] > h[2]) || !(h[5] > h[3]) ||
      !std::isfinite(h[4] - h[2]) || !std::isfinite(h[5] - h[3]))
    throw Error(path + ":" + std::to_string(header) +
                ": need integers NX, NY >= 2 (at most 1e7) and finite XMAX > XMIN, YMAX > YMIN");
  const int nx = static_cast<int>(h[0]), ny = static_cast<int>(h[1]);
  const CartesianGrid coarse = CartesianGrid::spanning({h[2], h[3]}, {h[4], h[5]}, nx, ny);
  const std::size_t count = static_cast<std::size_t>(nx) * ny;
  if (lines.size() - 1 != count)
    throw Error(path + ": " + std::to_string(lines.size() - 1) + " tensor lines for a " +
                std::to_string(nx) + " by " + std::to_string(ny) + " grid (need " +
                std::to_string(count) + ")");
  std::vector<Eigen::Matrix2d> M(count);
  for (std::size_t k = 0; k < count; ++k) {
    const auto& [line, text] = lines[k + 1];
    const auto v = numbers(path, line, text, 3, "'m11 m12 m22'");
    if (!(v[0] > 0.0 && v[0] * v[2] - v[1] * v[1] > 0.0))
      throw Error(path + ":" + std::to_string(line) +
                  ": the tensor is not symmetric positive definite (need m11 > 0 and "
                  "m11 m22 - m12^2 > 0)");
    M[k] << v[0], v[1], v[1], v[2];
  }
  return MetricField(coarse, std::move(M));
}

}  // namespace homesh
