#pragma once
// The examples of thesis Section 2.7 as Voronoi problems. The thesis gives
// no coordinates: the seeds and metrics here are constructed from its
// descriptions (and say how); the tests check the claims it makes about them,
// and scripts/voronoi_pictures.py draws them (via the hidden test case
// "[.voronoi_pictures]").
#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

#include "voronoi/engines/voronoi_problem.h"
#include "voronoi/grid/loop_distance.h"
#include "voronoi_test_support.h"

namespace homesh::test {

struct ThesisExample {
  std::string name;
  VoronoiProblem problem;
  std::vector<Eigen::Matrix2Xd> boundary;  ///< the domain's loops, for drawing
};

/// Fig 2.2: five seeds in the unit square under (a) a constant isotropic,
/// (c) a constant anisotropic (major axis at 30 degrees, aspect 1:0.35) and
/// (e) a variable metric (3 x 3 coarse grid, ellipses turning from 0 to 90
/// degrees and lengthening with x). kind: 0, 1, 2.
inline ThesisExample five_seeds(int kind, int n) {
  ThesisExample e;
  e.name = std::string("fig2_2_") + "ace"[kind];
  VoronoiProblem& p = e.problem;
  p.grid = CartesianGrid::spanning({0, 0}, {1, 1}, n, n);
  p.seeds.resize(2, 5);
  p.seeds << 0.5, 0.2, 0.82, 0.75, 0.28,  //
      0.48, 0.25, 0.22, 0.8, 0.72;
  if (kind == 1) p.metric = MetricField::constant(metric_from_axes(M_PI / 6, 1.0, 0.35));
  if (kind == 2) {
    std::vector<Eigen::Matrix2d> M;
    const CartesianGrid coarse = CartesianGrid::spanning({0, 0}, {1, 1}, 3, 3);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        M.push_back(metric_from_axes(M_PI / 4 * (i + j) / 2, 0.3 + 0.2 * i, 0.15));
    p.metric = MetricField(coarse, M);
  }
  return e;
}

/// Figs 2.4 and 2.5, after Labelle and Shewchuk (2003): ten seeds, each with
/// its own metric (semi-axes and angle chosen to differ strongly from their
/// neighbours'; seed 9, slow, sits 0.12 from seed 4, three times faster), held constant in the
/// seed's crystal (interpolated = false), or interpolated onto a 9 x 9 coarse grid by
/// inverse-distance (Shepard, power 2) weighting of the seeds' tensors (interpolated = true).
inline ThesisExample labelle_shewchuk(bool interpolated, int n) {
  struct Seed {
    double x, y, angle, h1, h2;
  };
  const std::vector<Seed> seeds{{0.15, 0.2, 0.0, 0.3, 0.3},    {0.5, 0.15, 0.3, 0.4, 0.1},
                                {0.85, 0.25, 1.2, 0.25, 0.08}, {0.3, 0.5, 0.8, 0.5, 0.1},
                                {0.55, 0.5, 0.0, 0.3, 0.3},    {0.8, 0.6, 2.0, 0.35, 0.07},
                                {0.15, 0.8, 0.2, 0.2, 0.2},    {0.45, 0.8, -0.5, 0.45, 0.06},
                                {0.75, 0.88, 0.9, 0.15, 0.15}, {0.62, 0.4, 1.5, 0.1, 0.1}};
  ThesisExample e;
  e.name = interpolated ? "fig2_5_labelle_shewchuk_interpolated" : "fig2_4_labelle_shewchuk";
  VoronoiProblem& p = e.problem;
  p.grid = CartesianGrid::spanning({0, 0}, {1, 1}, n, n);
  p.seeds.resize(2, static_cast<Eigen::Index>(seeds.size()));
  std::vector<Eigen::Matrix2d> own;
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    p.seeds.col(s) << seeds[s].x, seeds[s].y;
    own.push_back(metric_from_axes(seeds[s].angle, seeds[s].h1, seeds[s].h2));
  }
  if (!interpolated) {
    p.seed_metrics = own;
    return e;
  }
  const CartesianGrid coarse = CartesianGrid::spanning({0, 0}, {1, 1}, 9, 9);
  std::vector<Eigen::Matrix2d> M;
  for (int j = 0; j < coarse.ny; ++j)
    for (int i = 0; i < coarse.nx; ++i) {
      Eigen::Matrix2d sum = Eigen::Matrix2d::Zero();
      double weights = 0.0;
      for (std::size_t s = 0; s < seeds.size(); ++s) {
        const double w = 1.0 / (coarse.point(i, j) - p.seeds.col(s)).squaredNorm();
        sum += w * own[s];
        weights += w;
      }
      M.push_back(sum / weights);
    }
  p.metric = MetricField(coarse, M);
  return e;
}

/// A closed curve r(theta) about the origin, n points counter-clockwise
/// (clockwise if `clockwise`).
template <class R>
Eigen::Matrix2Xd polar_loop(R&& r, int n, bool clockwise) {
  Eigen::Matrix2Xd p(2, n);
  for (int k = 0; k < n; ++k) {
    const double a = (clockwise ? -2 : 2) * M_PI * k / n;
    p.col(k) << r(a) * std::cos(a), r(a) * std::sin(a);
  }
  return p;
}

/// Fig 2.6: the region between two closed curves with convex and concave
/// stretches, r = 0.9 + 0.12 cos 3t outside and 0.35 + 0.08 sin 2t inside,
/// 17 seeds (11 round the middle of the ring, 6 in the outer lobes and
/// bays), and an anisotropic metric whose major axis runs round the ring
/// (aspect 1:2).
inline ThesisExample non_convex_17(int n) {
  ThesisExample e;
  e.name = "fig2_6_non_convex_17";
  const auto outer = [](double t) { return 0.9 + 0.12 * std::cos(3 * t); };
  const auto inner = [](double t) { return 0.35 + 0.08 * std::sin(2 * t); };
  e.boundary = {polar_loop(outer, 720, false), polar_loop(inner, 360, true)};
  VoronoiProblem& p = e.problem;
  p.grid = CartesianGrid::spanning({-1.1, -1.1}, {1.1, 1.1}, n, n);
  p.domain = loop_signed_distance(p.grid, e.boundary, 8 * p.grid.ds());
  p.seeds.resize(2, 17);
  for (int k = 0; k < 11; ++k) {
    const double t = 2 * M_PI * (k + 0.3) / 11;
    const double r = 0.5 * (outer(t) + inner(t));
    p.seeds.col(k) << r * std::cos(t), r * std::sin(t);
  }
  for (int k = 0; k < 6; ++k) {
    const double t = M_PI * k / 3;  // lobes at k even, bays at k odd
    const double r = outer(t) - (k % 2 == 0 ? 0.12 : 0.1);
    p.seeds.col(11 + k) << r * std::cos(t), r * std::sin(t);
  }
  const CartesianGrid coarse = CartesianGrid::spanning({-1.1, -1.1}, {1.1, 1.1}, 12, 12);
  std::vector<Eigen::Matrix2d> M;
  for (int j = 0; j < coarse.ny; ++j)
    for (int i = 0; i < coarse.nx; ++i) {
      const Eigen::Vector2d x = coarse.point(i, j);
      M.push_back(metric_from_axes(std::atan2(x.y(), x.x()) + M_PI / 2, 0.4, 0.2));
    }
  p.metric = MetricField(coarse, M);
  return e;
}

/// NACA 0012 of unit chord from (0, 0) to (1, 0): `n` points per side,
/// cosine spacing, counter-clockwise (clockwise if `clockwise`).
inline Eigen::Matrix2Xd naca0012(int n, bool clockwise) {
  const auto yt = [](double x) {
    return 0.6 * (0.2969 * std::sqrt(x) - 0.126 * x - 0.3516 * x * x + 0.2843 * x * x * x -
                  0.1036 * x * x * x * x);
  };
  // Lower surface from the TE to the LE, then the upper one back: clockwise.
  Eigen::Matrix2Xd p(2, 2 * n);
  for (int k = 0; k < n; ++k) {
    const double x = 0.5 * (1 + std::cos(M_PI * k / n));
    p.col(k) << x, -yt(x);
    const double u = 0.5 * (1 - std::cos(M_PI * k / n));
    p.col(n + k) << u, yt(u);
  }
  if (!clockwise) p = p.rowwise().reverse().eval();
  return p;
}

/// Figs 2.7 and 2.8: a symmetric aerofoil (NACA 0012) in the square
/// [-0.9, 2.1] x [-1.5, 1.5], 130 seeds clustered across the aerofoil (two
/// rows of 16 at 0.04 and 0.12 from it) and the wake (six rows 0.04 apart
/// from y = -0.1, seeds 0.2 apart along them, every other row staggered by
/// 0.1),
/// a jittered lattice elsewhere; the metric isotropic, or of constant size
/// and stretching (0.2 by 0.04) with its major axis along the nearest point
/// of the aerofoil or of the wake line y = 0, x > 1.
inline ThesisExample aerofoil_130(bool anisotropic, int n) {
  ThesisExample e;
  e.name = anisotropic ? "fig2_7_aerofoil_aniso" : "fig2_7_aerofoil_iso";
  const Eigen::Matrix2Xd wing = naca0012(100, true);
  Eigen::Matrix2Xd box(2, 4);
  box << -0.9, 2.1, 2.1, -0.9,  //
      -1.5, -1.5, 1.5, 1.5;
  e.boundary = {box, wing};
  VoronoiProblem& p = e.problem;
  p.grid = CartesianGrid::spanning({-0.9, -1.5}, {2.1, 1.5}, n, n);
  p.domain = loop_signed_distance(p.grid, e.boundary, 8 * p.grid.ds());
  std::vector<Eigen::Vector2d> seeds;
  // Rows offset along the outward normal of the (clockwise) wing polygon,
  // equally spaced in arc length.
  std::vector<double> arc{0.0};
  for (Eigen::Index k = 0; k < wing.cols(); ++k)
    arc.push_back(arc.back() + (wing.col((k + 1) % wing.cols()) - wing.col(k)).norm());
  for (const auto& [offset, count] : {std::pair<double, int>{0.04, 16}, {0.12, 16}})
    for (int k = 0; k < count; ++k) {
      const double want = arc.back() * (k + 0.5) / count;
      Eigen::Index i = 0;
      while (arc[i + 1] < want) ++i;
      const Eigen::Vector2d a = wing.col(i), b = wing.col((i + 1) % wing.cols());
      const Eigen::Vector2d t = (b - a).normalized();
      seeds.push_back(a + (want - arc[i]) * t + offset * Eigen::Vector2d(-t.y(), t.x()));
    }
  for (int k = 0; k < 5; ++k)
    for (int row = 0; row < 6; ++row)
      seeds.emplace_back(1.15 + 0.2 * k + 0.1 * (row % 2), -0.1 + 0.04 * row);
  // The far field: a jittered lattice away from the clustered rows.
  const Eigen::Matrix2Xd jitter = test::uniform_seeds(200, 11, -0.08, 0.08);
  int m = 0;
  for (double y = -1.38; y < 1.4 && seeds.size() < 130; y += 0.3)
    for (double x = -0.76; x < 2.0 && seeds.size() < 130; x += 0.3, ++m) {
      const Eigen::Vector2d q = Eigen::Vector2d(x, y) + jitter.col(m);
      const bool near_wing = q.x() > -0.35 && q.x() < 1.3 && std::abs(q.y()) < 0.35;
      const bool near_wake = q.x() >= 1.3 && std::abs(q.y()) < 0.25;
      if (!near_wing && !near_wake) seeds.push_back(q);
    }
  p.seeds.resize(2, static_cast<Eigen::Index>(seeds.size()));
  for (std::size_t k = 0; k < seeds.size(); ++k) p.seeds.col(k) = seeds[k];
  const double h = 0.2;
  if (!anisotropic) {
    p.metric = MetricField::constant(Eigen::Matrix2d::Identity() / (h * h));
    return e;
  }
  const CartesianGrid coarse = CartesianGrid::spanning({-0.9, -1.5}, {2.1, 1.5}, 61, 61);
  std::vector<Eigen::Matrix2d> M;
  for (int j = 0; j < coarse.ny; ++j)
    for (int i = 0; i < coarse.nx; ++i) {
      const Eigen::Vector2d x = coarse.point(i, j);
      double best = std::hypot(std::max(0.0, 1.0 - x.x()), x.y());  // to the wake line
      double angle = 0.0;
      for (Eigen::Index k = 0; k < wing.cols(); ++k) {
        const double d = (wing.col(k) - x).norm();
        if (d >= best) continue;
        best = d;
        const Eigen::Vector2d t = wing.col((k + 1) % wing.cols()) - wing.col(k);
        angle = std::atan2(t.y(), t.x());
      }
      M.push_back(metric_from_axes(angle, h, h / 5));
    }
  p.metric = MetricField(coarse, M);
  return e;
}

}  // namespace homesh::test
