#pragma once
// The metric fields the voronoi stage builds on a coarse grid (Section 2.4):
// isotropic, from the sizes of a reference mesh, and boundary-layer-like,
// fine across the walls.
#include <Eigen/Core>
#include <vector>

#include "voronoi/metric/metric_field.h"

namespace homesh {

/// M = I / h^2 at each node of `coarse`, h interpolated linearly in the
/// triangle of (points, triangles) holding the node, or, for nodes in no
/// triangle, taken from the nearest node that is (breadth-first over the
/// coarse grid). points: 2 by n; h: n sizes > 0; triangles: 3 by T indices.
MetricField iso_metric_from_sizes(const CartesianGrid& coarse, const Eigen::Matrix2Xd& points,
                                  const Eigen::VectorXd& h, const Eigen::MatrixXi& triangles);

/// Mean length of the edges at each node of a triangulation (points 2 by n,
/// triangles 3 by T), each triangle at the node adding its two edges there
/// (an edge between two triangles counts twice); 0 for a node in no triangle.
Eigen::VectorXd mean_edge_length(const Eigen::Matrix2Xd& points, const Eigen::MatrixXi& triangles);

struct BoundaryLayerOptions {
  double wall_aspect = 5.0;  ///< h / h_n at the wall
  double thickness = 3.0;    ///< h_n reaches h at this many h from the wall
};

/// A boundary-layer-like metric: at a coarse node at distance d from the
/// nearest wall point, with t the wall's unit tangent there and h the size of
/// `iso` at the node, the sizes are h along t and
///
///   h_n = h (1/A + (1 - 1/A) min(1, d / (T h)))    across it,
///
/// A = wall_aspect, T = thickness (M = R^T diag(1/h^2, 1/h_n^2) R, Eq 2.7).
/// walls: polylines (2 by n each, n >= 2) finely sampled along the walls.
/// The coarse nodes hold these tensors (the growth's speeds); metric_at
/// gives them at the point itself (wall_layer.h), d its exact distance to the
/// walls' segments.
MetricField boundary_layer_metric(const MetricField& iso,
                                  const std::vector<Eigen::Matrix2Xd>& walls,
                                  const BoundaryLayerOptions& options = {});

}  // namespace homesh
