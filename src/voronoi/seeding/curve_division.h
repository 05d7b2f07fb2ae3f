#pragma once
// Boundary seeds along a curve from the metric: pieces of equal metric
// length, about 1 each (a metric of unit ball semi-axes h asks for edges of
// length h).
#include <Eigen/Core>
#include <vector>

#include "voronoi/metric/metric_field.h"

namespace homesh {

/// u: n + 1 increasing parameters and x: 2 by n + 1 points, a fine sampling
/// of a curve. Its metric length is L = sum_k |x_k+1 - x_k|_M, M the metric
/// at the chord's midpoint. Returns the m + 1 parameters, ends included, that
/// cut it into m = max(min_pieces, round(L)) pieces of metric length L / m
/// (linear in u between samples).
std::vector<double> divide_by_metric_length(const Eigen::VectorXd& u, const Eigen::Matrix2Xd& x,
                                            const MetricField& metric, int min_pieces);

}  // namespace homesh
