#pragma once
// Small planar helpers of the boundary-layer code: orientation, angles measured
// counter-clockwise, rotation, and numbers and points written for messages.
#include <Eigen/Core>
#include <cmath>
#include <sstream>
#include <string>

namespace homesh::layers_detail {

/// z component of a x b.
inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a(0) * b(1) - a(1) * b(0);
}

/// Twice the signed area of triangle (a, b, c): > 0 counter-clockwise.
inline double orient(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return cross(b - a, c - a);
}

/// Angle in [0, 2 pi) turning direction `from` counter-clockwise onto `to`.
inline double ccw_angle(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const double a = std::atan2(cross(from, to), from.dot(to));
  return a < 0 ? a + 2 * M_PI : a;
}

/// v rotated counter-clockwise by phi radians.
inline Eigen::Vector2d rotate(const Eigen::Vector2d& v, double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  return {c * v(0) - s * v(1), s * v(0) + c * v(1)};
}

/// v with 4 significant digits.
inline std::string number_text(double v) {
  std::ostringstream s;
  s.precision(4);
  s << v;
  return s.str();
}

/// "(x, y)" with 6 significant digits.
inline std::string point_text(const Eigen::Vector2d& p) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << p(0) << ", " << p(1) << ")";
  return s.str();
}

}  // namespace homesh::layers_detail
