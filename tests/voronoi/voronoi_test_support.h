#pragma once
// Shared fixtures of the Voronoi tests: reproducible seeds, circumcentres,
// the triangles of CGAL's Delaunay triangulation a grid partition can show,
// how far a seed set is from a degenerate one, and a triangle's mean ratio.
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

#include "voronoi/cleanup/metric_smoothing.h"
#include "voronoi/dual/cgal_delaunay.h"
#include "voronoi/dual/dual_triangulation.h"
#include "voronoi/grid/loop_distance.h"
#include "voronoi/metric/metric_field.h"

namespace homesh::test {

/// `count` seeds uniform in [lo, hi]^2 from mt19937(seed) (the generator is
/// fixed by the standard, the scaling written out, so the sets are the same
/// everywhere).
inline Eigen::Matrix2Xd uniform_seeds(int count, unsigned seed, double lo, double hi) {
  std::mt19937 gen(seed);
  Eigen::Matrix2Xd p(2, count);
  for (int k = 0; k < count; ++k)
    for (int d = 0; d < 2; ++d) p(d, k) = lo + (hi - lo) * (gen() / 4294967296.0);
  return p;
}

/// The domain level set of the unit square with a hole of radius 0.2 at its
/// centre (a polygon of `sides` sides), in a band of 8 cells, on grid g.
inline Eigen::VectorXd square_with_hole(const CartesianGrid& g, int sides) {
  Eigen::Matrix2Xd box(2, 4), hole(2, sides);
  box << 0, 1, 1, 0, 0, 0, 1, 1;
  for (int k = 0; k < sides; ++k) {
    const double a = -2 * M_PI * k / sides;  // clockwise: a hole
    hole.col(k) = Eigen::Vector2d(0.5, 0.5) + 0.2 * Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  return loop_signed_distance(g, {box, hole}, 8 * g.ds());
}

inline Eigen::Vector2d circumcentre(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                    const Eigen::Vector2d& c) {
  const Eigen::Vector2d u = b - a, v = c - a;
  const double d = 2.0 * (u.x() * v.y() - u.y() * v.x());
  return a + Eigen::Vector2d(v.y() * u.squaredNorm() - u.y() * v.squaredNorm(),
                             u.x() * v.squaredNorm() - v.x() * u.squaredNorm()) /
                 d;
}

/// Signed distance of p into the box [lo, hi]^2 (> 0 inside).
inline double inside_box(const Eigen::Vector2d& p, double lo, double hi) {
  return std::min({p.x() - lo, p.y() - lo, hi - p.x(), hi - p.y()});
}

/// How a Delaunay triangulation of `seeds` looks on a grid over [lo, hi]^2.
struct DelaunayInBox {
  /// The triangles whose circumcentre (Voronoi vertex) is inside the box,
  /// rotated to start at their smallest index: what a partition of the box can
  /// show.
  std::set<std::array<int, 3>> triangles;
  /// Smallest |distance to the box boundary| of a circumcentre.
  double border_margin = std::numeric_limits<double>::infinity();
  /// Smallest | |p - c| - R | over the triangles near or in the box and the
  /// other seeds p: how close the set is to four cocircular seeds.
  double incircle_margin = std::numeric_limits<double>::infinity();
};

/// In a constant metric M = L L^T the Voronoi diagram is the Euclidean one of
/// the seeds mapped by x -> L^T x (Lt), and its vertices map back by Lt^-1;
/// the margins are then metric lengths.
inline DelaunayInBox delaunay_in_box(const Eigen::Matrix2Xd& seeds, double lo, double hi,
                                     const Eigen::Matrix2d& Lt = Eigen::Matrix2d::Identity()) {
  DelaunayInBox out;
  const Eigen::Matrix2Xd mapped = Lt * seeds;
  const Eigen::Matrix2d back = Lt.inverse();
  for (const auto& t : cgal_delaunay_triangles(mapped)) {
    const Eigen::Vector2d c = circumcentre(mapped.col(t[0]), mapped.col(t[1]), mapped.col(t[2]));
    const double R = (c - mapped.col(t[0])).norm();
    const double depth = inside_box(back * c, lo, hi);
    out.border_margin = std::min(out.border_margin, std::abs(depth));
    if (depth > 0.0) out.triangles.insert(t);
    if (depth < -0.05 * (hi - lo)) continue;
    for (int q = 0; q < seeds.cols(); ++q)
      if (q != t[0] && q != t[1] && q != t[2])
        out.incircle_margin =
            std::min(out.incircle_margin, std::abs((mapped.col(q) - c).norm() - R));
  }
  return out;
}

// The first `count` seed sets of `size` seeds uniform in [0.05, 0.95]^2 in
// general position for a grid step ds in metric M: no four seeds within 2
// cells of cocircular (metric length), no Voronoi vertex within 8 cells of the
// border. (Uniform random sets are mostly near-degenerate somewhere: a
// Delaunay edge whose two triangles are nearly cocircular flips under the
// scheme's O(ds) errors, as it would under any perturbation of that size.)
inline std::vector<Eigen::Matrix2Xd> general_seed_sets(int count, int size, double ds,
                                                       const Eigen::Matrix2d& M) {
  const Eigen::Matrix2d Lt = M.llt().matrixL().transpose();
  const double cell = ds / metric_min_speed(M);
  std::vector<Eigen::Matrix2Xd> out;
  for (unsigned seed = 1; static_cast<int>(out.size()) < count; ++seed) {
    const Eigen::Matrix2Xd seeds = uniform_seeds(size, seed, 0.05, 0.95);
    const DelaunayInBox d = delaunay_in_box(seeds, 0.0, 1.0, Lt);
    if (d.incircle_margin >= 2 * cell && d.border_margin >= 8 * ds) out.push_back(seeds);
  }
  return out;
}

/// The triangles of a dual, rotated to start at their smallest index.
inline std::set<std::array<int, 3>> rotated(const std::vector<std::array<int, 3>>& triangles) {
  std::set<std::array<int, 3>> out;
  for (auto t : triangles) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.insert(t);
  }
  return out;
}

/// The mean ratio of the triangle with corners X's columns, in the plane's
/// own metric (1 for an equilateral triangle).
inline double euclidean_mean_ratio(const Eigen::Matrix<double, 2, 3>& X) {
  return metric_mean_ratio(X.col(0), X.col(1), X.col(2), Eigen::Matrix2d::Identity());
}

}  // namespace homesh::test
