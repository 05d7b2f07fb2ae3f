#pragma once
// The thesis tables kept as oracles in tests/data/thesis/ (read off the
// thesis): CSV tables such as table_3_2_distortion_representation.csv, and
// the two orderings of table_3_6_curvature_sensitivity.txt.
#include <string>
#include <vector>

namespace homesh {

/// A CSV table: lines starting with '#' are comments, the first other line
/// names the columns, each further line is a row named by its first cell.
struct ThesisTable {
  std::vector<std::string> columns;             ///< header, the first (row-name) column included
  std::vector<std::string> rows;                ///< first cell of each row
  std::vector<std::vector<std::string>> cells;  ///< [row][column], first column included

  bool has(const std::string& row, const std::string& column) const;
  /// The cell; throws homesh::Error naming the row and column if missing.
  const std::string& at(const std::string& row, const std::string& column) const;
};

/// Reads a thesis CSV table; throws homesh::Error if the file cannot be read.
ThesisTable read_thesis_table(const std::string& path);

/// An ordering of measures, most sensitive first: groups of measures the
/// thesis ranks equal ("Q8 = Q16").
using Ordering = std::vector<std::vector<std::string>>;

/// Table 3.6: the sensitivity orderings for convex (chi < 0) and concave
/// (chi > 0) boundary edges.
struct SensitivityOrderings {
  Ordering convex;
  Ordering concave;
};

/// Reads table_3_6_curvature_sensitivity.txt: the lines starting "Convex" and
/// "Concave", "Qa > Qb = Qc > ..." after the colon. Throws homesh::Error if
/// either is missing.
SensitivityOrderings read_sensitivity_orderings(const std::string& path);

}  // namespace homesh
