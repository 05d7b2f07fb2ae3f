#pragma once
// The two text inputs of the voronoi stage, read with errors that name the
// file and the line.
//
// Seed file: one seed per line, "x y" (two numbers, any further text is an
// error); blank lines and lines starting with '#' are skipped.
//
// Metric file: a coarse Cartesian grid of 2 by 2 symmetric positive definite
// tensors M (lengths |v|_M = sqrt(v^T M v): a unit ball of semi-axes h1, h2
// asks for edges of lengths h1, h2 along its axes; M = I / h^2 asks for size
// h). Blank lines and lines starting with '#' are skipped; then
//
//   grid NX NY XMIN YMIN XMAX YMAX
//   m11 m12 m22        (NX * NY lines, node (i, j) on line i + NX j: x fastest)
//
// NX, NY >= 2; the nodes span the box corner to corner (CartesianGrid::
// spanning). Between nodes the metric is the Shepard average of the cell's
// corners (thesis Section 2.4); outside the box, that of the nearest cell.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "voronoi/metric/metric_field.h"

namespace homesh {

struct SeedList {
  Eigen::Matrix2Xd points;  ///< 2 by n
  std::vector<int> lines;   ///< the 1-based line of each seed in its file
};

/// Throws homesh::Error "FILE:LINE: ..." for a line that is not two finite
/// numbers, "FILE: ..." if it cannot be read or holds no seed.
SeedList read_seed_file(const std::string& path);

/// Throws homesh::Error "FILE:LINE: ..." for a bad header, a line that is not
/// three finite numbers, a tensor that is not SPD (m11 > 0 and
/// m11 m22 - m12^2 > 0), missing or extra tensor lines.
MetricField read_metric_file(const std::string& path);

}  // namespace homesh
