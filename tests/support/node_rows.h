#pragma once
// Test data: rows "kind p c0 c1 ..." of a reference node file (Gmsh's or
// VTK's own parametric coordinates, one row per element kind and order), '#'
// lines comments.
#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace homesh::test {

/// The rows of `path`, keyed by (kind, p). Fails the test if it cannot be read.
inline std::map<std::pair<std::string, int>, std::vector<double>> node_rows(
    const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in.good());
  std::map<std::pair<std::string, int>, std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string kind;
    int p = 0;
    fields >> kind >> p;
    std::vector<double>& c = rows[{kind, p}];
    for (double value; fields >> value;) c.push_back(value);
  }
  return rows;
}

}  // namespace homesh::test
