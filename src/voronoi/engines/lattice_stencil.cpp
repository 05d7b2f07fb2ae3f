#include "voronoi/engines/lattice_stencil.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "core/error.h"

namespace homesh {
namespace {

double dot(const Eigen::Matrix2d& G, const Eigen::Vector2i& u, const Eigen::Vector2i& v) {
  return u.cast<double>().dot(G * v.cast<double>());
}

}  // namespace

Superbase obtuse_superbase(const Eigen::Matrix2d& G) {
  // Lagrange-Gauss: |b1| <= |b2| and |<b1, b2>| <= |b1|^2 / 2 at the end.
  // Stopping as soon as the reduced b2 is not shorter than b1 also ends the
  // loop on ties (<b1, b2> = +-|b1|^2 / 2 with |b2 - b1| = |b2|).
  Eigen::Vector2i b1(1, 0), b2(0, 1);
  for (;;) {
    if (dot(G, b1, b1) > dot(G, b2, b2)) std::swap(b1, b2);
    // Rounded half away from zero (std::lround, without the library call).
    const double q = dot(G, b1, b2) / dot(G, b1, b1);
    const long m = static_cast<long>(q < 0.0 ? q - 0.5 : q + 0.5);
    if (m == 0) break;
    b2 -= static_cast<int>(m) * b1;
    if (dot(G, b2, b2) >= dot(G, b1, b1)) break;
  }
  // <b1, b2> <= 0 makes (b1, b2, -b1 - b2) obtuse: <b1, b3> = -|b1|^2 - <b1, b2>
  // <= 0 and <b2, b3> = -|b2|^2 - <b1, b2> <= 0 by the reduction's bounds.
  if (dot(G, b1, b2) > 0.0) b2 = -b2;
  if (b1.x() * b2.y() - b1.y() * b2.x() < 0) std::swap(b1, b2);
  return {b1, b2};
}

LatticeStencil lattice_stencil(const Eigen::Matrix2d& M, double dx, double dy,
                               const LatticeStencil& near) {
  const Eigen::Matrix2d scale = Eigen::Vector2d(dx, dy).asDiagonal();
  const Eigen::Matrix2d G = scale * M * scale;
  const Superbase b = near.base();
  LatticeStencil st = near;
  st.g11 = dot(G, b.e1, b.e1), st.g12 = dot(G, b.e1, b.e2), st.g22 = dot(G, b.e2, b.e2);
  // Obtuse: <e1, e2> <= 0, <e1, e3> = -g11 - g12 <= 0, <e2, e3> = -g22 - g12 <= 0.
  if (st.g12 <= 0.0 && st.g11 + st.g12 >= 0.0 && st.g22 + st.g12 >= 0.0 && st.g11 > 0.0) return st;
  return lattice_stencil(M, dx, dy);
}

LatticeStencil lattice_stencil(const Eigen::Matrix2d& M, double dx, double dy) {
  const Eigen::Matrix2d scale = Eigen::Vector2d(dx, dy).asDiagonal();
  const Eigen::Matrix2d G = scale * M * scale;
  const Superbase b = obtuse_superbase(G);
  const int reach = std::max(b.e1.cwiseAbs().maxCoeff(), b.e2.cwiseAbs().maxCoeff());
  if (reach > std::numeric_limits<std::int16_t>::max())
    throw Error("voronoi: the metric is too anisotropic for the grid (a stencil offset of " +
                std::to_string(reach) + " cells)");
  LatticeStencil st;
  st.g11 = dot(G, b.e1, b.e1), st.g12 = dot(G, b.e1, b.e2), st.g22 = dot(G, b.e2, b.e2);
  st.e[0] = static_cast<std::int16_t>(b.e1.x()), st.e[1] = static_cast<std::int16_t>(b.e1.y());
  st.e[2] = static_cast<std::int16_t>(b.e2.x()), st.e[3] = static_cast<std::int16_t>(b.e2.y());
  return st;
}

}  // namespace homesh
