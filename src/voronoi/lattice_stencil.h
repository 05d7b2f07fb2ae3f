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
#include <array>
#include <cmath>
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
/// (physical vectors U = vec[k], V = vec[k + 1], W = V - U), all in M:
/// A = |U|^2, B = <U, W>, C = |W|^2, det = A C - B^2.
struct SectorConstants {
  double A = 0, B = 0, C = 0, det = 0;
};

SectorConstants sector_constants(const Eigen::Matrix2d& M, const Eigen::Vector2d& U,
                                 const Eigen::Vector2d& V);

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

/// The hexagon of one metric on a grid of steps dx, dy, with its lengths and
/// sector constants.
struct LatticeStencil {
  std::array<Eigen::Vector2i, 6> offset;  ///< grid offsets, counter-clockwise
  std::array<Eigen::Vector2d, 6> vec;     ///< physical vectors (i dx, j dy)
  std::array<double, 6> length{};         ///< |vec[k]|_M
  std::array<double, 6> euclid{};         ///< |vec[k]|
  std::array<SectorConstants, 6> sector;  ///< between vec[k] and vec[(k + 1) % 6]
  double max_length = 0.0;                ///< largest length
};

/// The FM-LBR stencil of the SPD metric M on a grid of steps dx, dy.
LatticeStencil lattice_stencil(const Eigen::Matrix2d& M, double dx, double dy);

}  // namespace homesh
