#include "optim/thesis_tables.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace homesh {
namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream ss(text);
  for (std::string part; std::getline(ss, part, separator);) {
    const size_t a = part.find_first_not_of(" \t\r");
    const size_t b = part.find_last_not_of(" \t\r");
    parts.push_back(a == std::string::npos ? std::string() : part.substr(a, b - a + 1));
  }
  return parts;
}

Ordering parse_ordering(const std::string& text) {
  Ordering ordering;
  for (const std::string& group : split(text, '>')) ordering.push_back(split(group, '='));
  return ordering;
}

}  // namespace

bool ThesisTable::has(const std::string& row, const std::string& column) const {
  const auto r = std::find(rows.begin(), rows.end(), row);
  const auto c = std::find(columns.begin(), columns.end(), column);
  return r != rows.end() && c != columns.end() &&
         static_cast<size_t>(c - columns.begin()) < cells[r - rows.begin()].size();
}

const std::string& ThesisTable::at(const std::string& row, const std::string& column) const {
  if (!has(row, column)) throw Error("thesis table has no cell (" + row + ", " + column + ")");
  const auto r = std::find(rows.begin(), rows.end(), row) - rows.begin();
  const auto c = std::find(columns.begin(), columns.end(), column) - columns.begin();
  return cells[r][c];
}

ThesisTable read_thesis_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot read thesis table " + path);
  ThesisTable table;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells = split(line, ',');
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    if (table.columns.empty()) {
      table.columns = cells;
      continue;
    }
    table.rows.push_back(cells.front());
    table.cells.push_back(cells);
  }
  return table;
}

SensitivityOrderings read_sensitivity_orderings(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot read thesis table " + path);
  SensitivityOrderings orderings;
  for (std::string line; std::getline(in, line);) {
    const size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    if (line.rfind("Convex", 0) == 0) orderings.convex = parse_ordering(line.substr(colon + 1));
    if (line.rfind("Concave", 0) == 0) orderings.concave = parse_ordering(line.substr(colon + 1));
  }
  if (orderings.convex.empty() || orderings.concave.empty()) {
    throw Error(path + " lacks the Convex and Concave orderings");
  }
  return orderings;
}

}  // namespace homesh
