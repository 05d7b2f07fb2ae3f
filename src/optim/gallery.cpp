#include "optim/gallery.h"

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/mesh.h"

namespace homesh {
namespace {

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
  return cells;
}

std::string trim_comment(const std::string& line) {
  const size_t start = line.find_first_not_of("# ");
  return start == std::string::npos ? std::string() : line.substr(start);
}

}  // namespace

std::vector<GalleryElement> read_gallery(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot read gallery file " + path);
  std::vector<GalleryElement> gallery;
  std::vector<std::vector<Eigen::Vector2d>> points;
  std::string comment;
  bool header = false;
  int line_number = 0;
  const auto fail = [&](const std::string& why) {
    throw Error(path + ":" + std::to_string(line_number) + ": " + why);
  };
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (line.empty()) continue;
    if (line[0] == '#') {
      const std::string text = trim_comment(line);
      comment += text.empty() ? "" : (comment.empty() ? "" : " ") + text;
      continue;
    }
    if (!header) {
      if (line != "element,order,node,x,y") fail("expected the header element,order,node,x,y");
      header = true;
      comment.clear();
      continue;
    }
    const std::vector<std::string> cells = split_csv(line);
    if (cells.size() != 5) fail("expected 5 columns");
    int order = 0, node = 0;
    double x = 0, y = 0;
    try {
      order = std::stoi(cells[1]);
      node = std::stoi(cells[2]);
      x = std::stod(cells[3]);
      y = std::stod(cells[4]);
    } catch (const std::exception&) {
      fail("bad number");
    }
    if (gallery.empty() || gallery.back().name != cells[0]) {
      if (node != 0) fail("element " + cells[0] + " must start at node 0");
      if (order < 1 || order > kMaxOrder) fail("bad order " + cells[1]);
      gallery.push_back({cells[0], order, {}, comment});
      points.emplace_back();
      comment.clear();
    }
    if (order != gallery.back().order) fail("order changes within element " + cells[0]);
    if (node != static_cast<int>(points.back().size())) fail("nodes out of order");
    points.back().emplace_back(x, y);
  }
  if (!header) throw Error("gallery file " + path + " has no header");
  for (size_t e = 0; e < gallery.size(); ++e) {
    const int expected = triangle_node_count(gallery[e].order);
    if (static_cast<int>(points[e].size()) != expected) {
      throw Error(path + ": element " + gallery[e].name + " of order " +
                  std::to_string(gallery[e].order) + " needs " + std::to_string(expected) +
                  " nodes, got " + std::to_string(points[e].size()));
    }
    gallery[e].nodes.resize(2, expected);
    for (int k = 0; k < expected; ++k) gallery[e].nodes.col(k) = points[e][k];
  }
  return gallery;
}

const GalleryElement& gallery_element(const std::vector<GalleryElement>& gallery,
                                      const std::string& name) {
  for (const GalleryElement& e : gallery) {
    if (e.name == name) return e;
  }
  throw Error("no element " + name + " in the gallery");
}

}  // namespace homesh
