#include "gmsh/metric_view.h"

#include <gmsh.h>

#include <algorithm>
#include <deque>
#include <utility>
#include <vector>

#include "core/error.h"

namespace homesh::gmsh_adapter {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// "view" then the digits of a tag.
bool names_loaded_view(const std::string& spec) {
  return spec.size() > 4 && spec.size() < 14 && spec.rfind("view", 0) == 0 &&
         std::all_of(spec.begin() + 4, spec.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

bool names_metric_view(const std::string& spec) {
  return names_loaded_view(spec) || ends_with(spec, ".pos") || ends_with(spec, ".msh");
}

int metric_view_tag(const std::string& spec) {
  std::vector<int> tags;
  if (names_loaded_view(spec)) {
    const int tag = std::stoi(spec.substr(4));
    gmsh::view::getTags(tags);
    if (std::find(tags.begin(), tags.end(), tag) == tags.end())
      throw Error("metric " + spec + ": no view of tag " + std::to_string(tag) + " (" +
                  std::to_string(tags.size()) + " views loaded)");
    return tag;
  }
  std::vector<int> before;
  gmsh::view::getTags(before);
  gmsh::merge(spec);
  gmsh::view::getTags(tags);
  if (tags.size() == before.size()) throw Error("metric " + spec + ": the file holds no view");
  return tags.back();
}

MetricField metric_from_view(int tag, const CartesianGrid& coarse) {
  const int n = coarse.node_count();
  std::vector<Eigen::Matrix2d> M(n);
  std::vector<int> from(n, -1);  // the node whose probe gives node k's tensor
  std::deque<int> queue;
  std::vector<double> value;
  for (int j = 0; j < coarse.ny; ++j)
    for (int i = 0; i < coarse.nx; ++i) {
      const int k = coarse.index(i, j);
      const Eigen::Vector2d p = coarse.point(i, j);
      gmsh::view::probe(tag, p.x(), p.y(), 0.0, value, 0);
      if (value.empty()) continue;
      if (value.size() != 9)
        throw Error("metric view " + std::to_string(tag) + ": " + std::to_string(value.size()) +
                    " components per value, a metric needs a tensor (9)");
      const double xy = 0.5 * (value[1] + value[3]);
      M[k] << value[0], xy, xy, value[4];
      from[k] = k;
      queue.push_back(k);
    }
  if (queue.empty())
    throw Error("metric view " + std::to_string(tag) + " covers none of the domain's box");
  // Breadth-first from the probed nodes: each other node copies the nearest.
  while (!queue.empty()) {
    const int k = queue.front();
    queue.pop_front();
    const int i = k % coarse.nx, j = k / coarse.nx;
    for (const auto& [di, dj] : {std::pair<int, int>{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const int a = i + di, b = j + dj;
      if (a < 0 || b < 0 || a >= coarse.nx || b >= coarse.ny) continue;
      const int z = coarse.index(a, b);
      if (from[z] >= 0) continue;
      from[z] = from[k];
      M[z] = M[from[k]];
      queue.push_back(z);
    }
  }
  try {
    return MetricField(coarse, std::move(M));
  } catch (const Error& e) {
    throw Error("metric view " + std::to_string(tag) + ": " + e.what());
  }
}

}  // namespace homesh::gmsh_adapter
