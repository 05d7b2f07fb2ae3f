#pragma once
// The Delaunay triangulation of seeds in an anisotropic metric, as the dual of
// their Voronoi diagram in a locally constant metric: Lawson's edge flips
// (Lawson, "Software for C1 surface interpolation", 1977) from the Euclidean
// constrained triangulation, each edge judged by the in-circle test in the
// metric of its quad (the mean of the metric at its four corners), as in the
// anisotropic Delaunay kernels of Borouchaki, George, Hecht, Laug and Saltel,
// "Delaunay mesh generation governed by metric specifications", Finite
// Elements in Analysis and Design 25, 1997. An edge that passes is locally
// Delaunay in that metric: its two seeds' Voronoi cells in it share a side.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "voronoi/metric/metric_field.h"

namespace homesh {

/// Whether d lies strictly inside the circle through a, b, c (counter-
/// clockwise) in the constant metric M (the points mapped by M's Cholesky
/// factor; relative tolerance 1e-12).
bool in_metric_circle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                      const Eigen::Vector2d& d, const Eigen::Matrix2d& M);

struct MetricDelaunay {
  int flips = 0;
  /// Triangles with an edge that is still not locally Delaunay (flips that
  /// would invert a triangle, or the sweeps ran out): not from the dual.
  long not_delaunay = 0;
};

/// Flips the edges of `triangles` (counter-clockwise, indices into x) that
/// are not locally Delaunay in the metric and whose quad is convex, never a
/// segment of `segments`, sweeping until none flips (at most max_sweeps).
MetricDelaunay metric_delaunay_flips(const Eigen::Matrix2Xd& x,
                                     std::vector<std::array<int, 3>>& triangles,
                                     const std::vector<std::array<int, 2>>& segments,
                                     const MetricField& metric, int max_sweeps = 1000);

}  // namespace homesh
