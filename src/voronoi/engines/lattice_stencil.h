#pragma once
// The anisotropic fast-marching stencil of Mirebeau's lattice basis reduction
// (FM-LBR): J.-M. Mirebeau, "Anisotropic fast-marching on Cartesian grids
// using lattice basis reduction", SIAM J. Numer. Anal. 52(4) 1573-1599, 2014.
//
// For a metric M (lengths |v|_M = sqrt(v^T M v), convention of
// metric_field.h) the stencil at a node is the hexagon of grid offsets
//
//   e1, e1 + e2 (= -e3), e2, -e1, e3, -e2      (counter-clockwise)
//
// of an M-obtuse superbase (e1, e2, e3): e1 + e2 + e3 = 0, det(e1, e2) = 1 and
// <ei, ej>_M <= 0 for i != j. Consecutive offsets then make M-acute angles,
// which makes the Hopf-Lax update below causal (the new value exceeds the
// values it is computed from), so the nodes can be accepted in increasing
// order as in Dijkstra's algorithm, at any anisotropy. The offsets grow like
// the anisotropy ratio in the worst case; the number of neighbours stays 6.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <limits>

namespace homesh {

/// The superbase (e1, e2) as grid offsets, e3 = -e1 - e2.
struct Superbase {
  Eigen::Vector2i e1, e2;
};

/// An M-obtuse superbase for the Gram matrix G of the grid's unit offsets
/// (G = diag(dx, dy) M diag(dx, dy)): Lagrange-Gauss reduction, then a sign
/// choice (Mirebeau 2014, Section 2; Conway and Sloane's obtuse superbase).
/// G must be symmetric positive definite.
Superbase obtuse_superbase(const Eigen::Matrix2d& G);

/// Offset k (0..5, counter-clockwise) of the hexagon of superbase b.
inline Eigen::Vector2i hexagon_offset(const Superbase& b, int k) {
  static constexpr int c1[6] = {1, 1, 0, -1, -1, 0}, c2[6] = {0, 1, 1, 0, -1, -1};
  return c1[k] * b.e1 + c2[k] * b.e2;
}

/// What the update needs of the sector between hexagon offsets k and k + 1
/// (vectors U = offset k, V = offset k + 1, W = V - U), all in the metric:
/// A = |U|^2, B = <U, W>, C = |W|^2, det = A C - B^2.
struct SectorConstants {
  double A = 0, B = 0, C = 0, det = 0;
};

/// The Hopf-Lax update of a node x from the segment [x + U, x + V] on which
/// the arrival time is interpolated linearly between a (at x + U) and b:
///
///   t = min over 0 < lambda < 1 of |U + lambda (V - U)|_M + a + lambda (b - a).
///
/// Setting the derivative to zero gives |y|^2_M = det / (C - (b - a)^2) and
/// lambda = (-(b - a) |y|_M - B) / C. Returns +infinity if the minimum is at
/// an end of the segment (those are the one-sided updates a + |U|_M and
/// b + |V|_M, done separately).
inline double hopf_lax(const SectorConstants& s, double a, double b) {
  const double d = b - a;
  const double gap = s.C - d * d;
  if (gap <= 0.0) return std::numeric_limits<double>::infinity();
  const double r = std::sqrt(s.det / gap);
  const double lambda = (-d * r - s.B) / s.C;
  if (!(lambda > 0.0 && lambda < 1.0)) return std::numeric_limits<double>::infinity();
  return r + a + lambda * d;
}

/// The FM-LBR stencil of one metric M on a grid of steps dx, dy, in grid
/// units: lengths are those of the physical vectors (i dx, j dy) of grid
/// offsets (i, j) in M. Kept as the superbase and its Gram values in M,
/// g11 = |e1|^2, g12 = <e1, e2>, g22 = |e2|^2: every sector's constants are
/// sums of them (det(e1, e2) = 1 makes det = g11 g22 - g12^2 in all six),
/// and the length of any grid vector v follows from its coordinates in the
/// superbase, c = [e1 e2]^-1 v (an integer inverse). 32 bytes, two to a
/// cache line: the fast-marching engine keeps one per node in a metric field.
struct alignas(32) LatticeStencil {
  double g11 = 0, g12 = 0, g22 = 0;  ///< Gram values of the superbase
  std::int16_t e[4] = {0, 0, 0, 0};  ///< the superbase: e1 = (e[0], e[1]), e2 = (e[2], e[3])

  Superbase base() const { return {{e[0], e[1]}, {e[2], e[3]}}; }
  /// Offset k (0..5, counter-clockwise).
  Eigen::Vector2i offset(int k) const { return hexagon_offset(base(), k); }
  /// |offset k|^2 in the metric: offsets k and k + 3 are opposite, and
  /// offset 1 is e1 + e2.
  double gram(int k) const {
    switch (k % 3) {
      case 0:
        return g11;
      case 1:
        return g11 + g22 + 2.0 * g12;
      default:
        return g22;
    }
  }
  /// |offset k| in the metric.
  double length(int k) const { return std::sqrt(gram(k)); }
  /// |v|^2 in the metric, for v in grid units.
  double norm2(const Eigen::Vector2d& v) const {
    const double c1 = e[3] * v.x() - e[2] * v.y(), c2 = e[0] * v.y() - e[1] * v.x();
    return g11 * c1 * c1 + 2.0 * g12 * c1 * c2 + g22 * c2 * c2;
  }
  /// The constants of the sector between offsets k and k + 1 (mod 6):
  /// (U, W) = (e1, e2), (e1 + e2, -e1), (e2, -e1 - e2) for k = 0, 1, 2, and
  /// their opposites (the same constants) for k + 3.
  SectorConstants sector(int k) const {
    SectorConstants s;
    switch (k % 3) {
      case 0:
        s.A = g11, s.B = g12, s.C = g22;
        break;
      case 1:
        s.A = g11 + g22 + 2.0 * g12, s.B = -(g11 + g12), s.C = g11;
        break;
      default:
        s.A = g22, s.B = -(g12 + g22), s.C = g11 + g22 + 2.0 * g12;
    }
    s.det = g11 * g22 - g12 * g12;
    return s;
  }
};

/// The FM-LBR stencil of the SPD metric M on a grid of steps dx, dy; throws
/// homesh::Error if an offset does not fit 16 bits (anisotropy beyond ~10^4
/// in grid cells).
LatticeStencil lattice_stencil(const Eigen::Matrix2d& M, double dx, double dy);
/// The same, trying first the superbase of `near` (a stencil of a nearby
/// metric): kept if it is M-obtuse too, which in a smooth metric field it
/// nearly always is, and saves the reduction. Any M-obtuse superbase makes
/// the stencil of M (Mirebeau 2014: unique up to order and signs but where
/// an angle is right).
LatticeStencil lattice_stencil(const Eigen::Matrix2d& M, double dx, double dy,
                               const LatticeStencil& near);

}  // namespace homesh
