#pragma once
// Brute-force minimisation on a structured grid, the verification the thesis
// runs beside PRAXIS (Section 3.8.2: "a brute force approach utilising a fine
// structured background mesh ... to find the exact minimum distortion location").
#include <Eigen/Core>
#include <functional>

namespace homesh {

struct GridSearchOptions {
  int points_per_axis = 101;  ///< grid points along each axis of the box (>= 2)
  /// Zoom-ins: each re-grids the box of +-2 cells around the best point so far
  /// with the same number of points.
  int refinements = 2;
};

struct GridSearchResult {
  Eigen::VectorXd x;  ///< best grid point
  double value = 0;   ///< f there
  int evaluations = 0;
  double spacing = 0;  ///< grid spacing of the last level (largest over the axes)
};

/// Minimum of f over the box [lo, hi] (both of the problem's dimension d,
/// lo < hi) sampled on points_per_axis^d grid points, then refined. A grid
/// finds the global minimum of the sampled values, to within `spacing` of a
/// minimiser if f is smooth near it; NaN values are skipped. Throws
/// homesh::Error on a bad box or options.
GridSearchResult grid_search(const std::function<double(const Eigen::VectorXd&)>& f,
                             const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                             const GridSearchOptions& opt = {});

}  // namespace homesh
