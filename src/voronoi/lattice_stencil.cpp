#include "voronoi/lattice_stencil.h"

#include <algorithm>
#include <cmath>
#include <utility>

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
    const long m = std::lround(dot(G, b1, b2) / dot(G, b1, b1));
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

SectorConstants sector_constants(const Eigen::Matrix2d& M, const Eigen::Vector2d& U,
                                 const Eigen::Vector2d& V) {
  const Eigen::Vector2d W = V - U;
  SectorConstants s;
  s.A = U.dot(M * U);
  s.B = U.dot(M * W);
  s.C = W.dot(M * W);
  s.det = s.A * s.C - s.B * s.B;
  return s;
}

LatticeStencil lattice_stencil(const Eigen::Matrix2d& M, double dx, double dy) {
  const Eigen::Matrix2d scale = Eigen::Vector2d(dx, dy).asDiagonal();
  const Superbase b = obtuse_superbase(scale * M * scale);
  LatticeStencil st;
  for (int k = 0; k < 6; ++k) {
    st.offset[k] = hexagon_offset(b, k);
    st.vec[k] = scale * st.offset[k].cast<double>();
    st.length[k] = std::sqrt(st.vec[k].dot(M * st.vec[k]));
    st.euclid[k] = st.vec[k].norm();
    st.max_length = std::max(st.max_length, st.length[k]);
  }
  for (int k = 0; k < 6; ++k) st.sector[k] = sector_constants(M, st.vec[k], st.vec[(k + 1) % 6]);
  return st;
}

}  // namespace homesh
