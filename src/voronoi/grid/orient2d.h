#pragma once
// Exact orientation predicate for points with double coordinates, after
// Shewchuk, "Adaptive precision floating-point arithmetic and fast robust
// geometric predicates", Discrete Comput. Geom. 18 (1997): a floating-point
// filter, then exact expansion arithmetic when the filter cannot decide.
#include <Eigen/Core>

namespace homesh {

/// Sign of det [a - c, b - c] = (ax - cx)(by - cy) - (ay - cy)(bx - cx):
/// +1 if a, b, c turn counter-clockwise, -1 clockwise, 0 if collinear.
/// Exact for all finite inputs whose products neither overflow nor underflow.
int orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

}  // namespace homesh
