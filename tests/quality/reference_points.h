#pragma once
// Random points of the reference triangle, shared by the Bezier tests.
#include <Eigen/Core>
#include <random>

namespace homesh::test {

/// A point uniformly distributed on the reference triangle (u, v >= 0,
/// u + v <= 1): a point of the unit square, reflected into the triangle.
inline Eigen::Vector2d random_reference_point(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Eigen::Vector2d uv(unit(rng), unit(rng));
  if (uv.sum() > 1.0) uv = Eigen::Vector2d(1.0 - uv(1), 1.0 - uv(0));
  return uv;
}

}  // namespace homesh::test
