#include "voronoi/seeding/metric_seeding.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core/error.h"
#include "voronoi/seeding/spaced_seeds.h"

namespace homesh {
namespace {

constexpr double kFrontLink = 1.6;  // front seeds this close in the metric stay one chain
constexpr double kCornerMin = 75, kCornerMax = 140;  // corners that get a seed (degrees)
constexpr double kCornerGap = 0.8;                   // and its gap to the walls, times boundary_gap
// The lattice's edge (metric length) and the random candidates each lattice
// seed throws besides its six (SeedingOptions::interior). On the plate with a
// hole at 3e4 triangles, 0, 4 and 16 random candidates made Gmsh's mean ICN
// 0.9891, 0.9895 and 0.9890 after the Lloyd iterations and the clean-up;
// steps of 0.95 and 1.05 changed the triangle count by +-4 % and the mean
// by less than 0.0002 (docs/voronoi.md).
constexpr double kLatticeStep = 1.0;
constexpr int kLatticeTries = 4;

}  // namespace

// Rebay (J Comput Phys 106, 1993): rows of apexes, advancing from the boundary.
FrontSeeds metric_front_seeds(const CartesianGrid& g, const Eigen::VectorXd& domain,
                              const MetricField& metric, const Eigen::Matrix2Xd& boundary_seeds,
                              const std::vector<std::array<int, 2>>& segments,
                              const SeedingOptions& o) {
  const Eigen::Vector2d lo = g.origin;
  const Eigen::Vector2d hi = g.point(g.nx - 1, g.ny - 1);
  const DomainTest test{g, domain};
  SpacedSeeds buckets(
      lo, hi, std::max(metric.min_speed() * o.front_spacing, 1e-9 * (hi - lo).norm()), metric);
  for (Eigen::Index k = 0; k < boundary_seeds.cols(); ++k) buckets.add(boundary_seeds.col(k));
  const double equilateral = std::sqrt(3.0) / 2;
  // Keeps q if its metric ball of radius gap lies in the domain and it is
  // spaced from the seeds so far.
  const auto place = [&](const Eigen::Vector2d& q, double gap) {
    const Eigen::Matrix2d Mq = metric.metric_at(q);
    const Eigen::Matrix2d root_inv =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(Mq).operatorInverseSqrt();
    const double reach = 2.0 * o.front_spacing * metric_max_speed(Mq);
    if (!test.ball_inside(q, root_inv, gap) || !buckets.spaced(q, Mq, o.front_spacing, reach))
      return false;
    buckets.add(q, Mq);
    return true;
  };
  // The apex of (a, b), if it is kept.
  const auto apex = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d mid = 0.5 * (a + b);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(metric.metric_at(mid));
    const Eigen::Vector2d u = eig.operatorSqrt() * (b - a);
    if (u.squaredNorm() == 0.0) return std::optional<Eigen::Vector2d>();
    const Eigen::Vector2d n = eig.operatorInverseSqrt() * Eigen::Vector2d(-u.y(), u.x());
    Eigen::Vector2d q = mid + equilateral * n;  // equilateral in M(mid)
    for (int step = 0; step < 3; ++step) {
      const Eigen::Matrix2d Mq = metric.metric_at(q);
      const double L = std::sqrt((b - a).dot(Mq * (b - a)));
      const double t = std::clamp(std::sqrt(std::max(0.0, 1.0 - 0.25 * L * L)),
                                  0.6 * equilateral * L, 1.5 * equilateral * L);
      q = mid + t / std::sqrt(n.dot(Mq * n)) * n;
    }
    return place(q, o.boundary_gap) ? std::optional<Eigen::Vector2d>(q)
                                    : std::optional<Eigen::Vector2d>();
  };
  // The front: chains of points, each segment with the domain on its left.
  struct Chain {
    std::vector<Eigen::Vector2d> p;
    bool closed = false;
  };
  std::vector<Chain> chains;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    if (k == 0 || segments[k][0] != segments[k - 1][1])
      chains.push_back({{boundary_seeds.col(segments[k][0])}});
    chains.back().p.push_back(boundary_seeds.col(segments[k][1]));
  }
  for (Chain& c : chains)
    if (c.p.size() > 2 && c.p.front() == c.p.back()) {
      c.p.pop_back();
      c.closed = true;
    }
  FrontSeeds out;
  std::vector<Eigen::Vector2d> seeds;
  // Corners of kCornerMin to kCornerMax degrees (in the metric at the
  // corner) first: a seed on the bisector, as far from the corner as its two
  // segments are long, splits the corner into two triangles, where one
  // triangle spanning a right angle would have mean ratio sqrt(3)/2.
  if (o.front_rows > 0)
    for (const Chain& c : chains) {
      const std::size_t n = c.p.size();
      for (std::size_t k = c.closed ? 0 : 1; k < (c.closed ? n : n - 1); ++k) {
        const Eigen::Vector2d a = c.p[(k + n - 1) % n], corner = c.p[k], b = c.p[(k + 1) % n];
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(metric.metric_at(corner));
        const Eigen::Vector2d u = eig.operatorSqrt() * (a - corner),
                              w = eig.operatorSqrt() * (b - corner);
        // The domain's angle, from w counter-clockwise to u.
        double angle = std::atan2(w.x() * u.y() - w.y() * u.x(), w.dot(u));
        if (angle < 0) angle += 2 * M_PI;
        if (angle < kCornerMin * M_PI / 180 || angle > kCornerMax * M_PI / 180) continue;
        const Eigen::Rotation2Dd half(0.5 * angle);
        const Eigen::Vector2d q =
            corner +
            0.5 * (u.norm() + w.norm()) * (eig.operatorInverseSqrt() * (half * w.normalized()));
        if (place(q, kCornerGap * o.boundary_gap)) seeds.push_back(q);
      }
    }
  for (int row = 0; row < o.front_rows && !chains.empty(); ++row) {
    std::vector<Chain> next;
    for (const Chain& c : chains) {
      const std::size_t n = c.p.size(), ns = c.closed ? n : n - 1;
      std::vector<Eigen::Vector2d> kept;
      for (std::size_t k = 0; k < ns; ++k)
        if (const auto q = apex(c.p[k], c.p[(k + 1) % n])) kept.push_back(*q);
      seeds.insert(seeds.end(), kept.begin(), kept.end());
      // The next row's chains: the kept apexes in order, linked where they
      // are within kFrontLink in the metric (skipping rejected apexes, so a
      // growing size thins the row), broken elsewhere.
      const auto linked = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        const Eigen::Vector2d v = b - a;
        return v.dot(0.5 * (metric.metric_at(a) + metric.metric_at(b)) * v) <=
               kFrontLink * kFrontLink;
      };
      const std::size_t m = kept.size();
      if (m < 2) continue;
      std::size_t start = 0;  // a chain starts after a break
      bool all = true;
      for (std::size_t k = 0; k < m; ++k)
        if (!(k + 1 < m || c.closed) || !linked(kept[k], kept[(k + 1) % m])) {
          start = (k + 1) % m;
          all = false;
          break;
        }
      if (all && c.closed) {
        next.push_back({kept, true});
        continue;
      }
      Chain cur;
      for (std::size_t j = 0; j < m; ++j) {
        const std::size_t k = (start + j) % m;
        cur.p.push_back(kept[k]);
        if (j + 1 == m || !linked(kept[k], kept[(k + 1) % m])) {
          if (cur.p.size() > 1) next.push_back(cur);
          cur.p.clear();
        }
      }
    }
    if (row == 0) out.first_row = static_cast<Eigen::Index>(seeds.size());
    chains = std::move(next);
  }
  out.seeds.resize(2, static_cast<Eigen::Index>(seeds.size()));
  for (std::size_t k = 0; k < seeds.size(); ++k) out.seeds.col(k) = seeds[k];
  return out;
}

Eigen::Matrix2Xd metric_interior_seeds(const CartesianGrid& g, const Eigen::VectorXd& domain,
                                       const MetricField& metric,
                                       const Eigen::Matrix2Xd& boundary_seeds,
                                       const SeedingOptions& o) {
  if (o.interior != "lattice" && o.interior != "poisson")
    throw Error("voronoi seeding: interior '" + o.interior + "' is neither lattice nor poisson");
  const Eigen::Vector2d lo = g.origin;
  const Eigen::Vector2d hi = g.point(g.nx - 1, g.ny - 1);
  const DomainTest test{g, domain};
  // Buckets as small as the smallest semi-axis of the field; neighbours are
  // searched within spacing (1 + annulus) times twice the local largest
  // semi-axis (a graded metric changes by less than 2 over that distance).
  double h_min = metric.min_speed();
  SpacedSeeds buckets(lo, hi, std::max(h_min * o.spacing, 1e-9 * (hi - lo).norm()), metric);
  std::vector<Eigen::Vector2d> active;
  for (int k = 0; k < boundary_seeds.cols(); ++k) {
    buckets.add(boundary_seeds.col(k));
    active.push_back(boundary_seeds.col(k));
  }
  std::mt19937 gen(o.random_seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector2d> interior;
  // How far the seeds that might be within a candidate's annulus lie, from
  // the metric's eigenvalues at it (twice its longest semi-axis).
  const auto reach_of = [&](const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>& eig) {
    return 2.0 * o.spacing * (1 + o.annulus) / std::sqrt(eig.eigenvalues()(0));
  };
  const auto try_add = [&](const Eigen::Vector2d& q) {
    // The spacing first: it rejects most candidates, and costs less.
    const Eigen::Matrix2d Mq = metric.metric_at(q);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(Mq);
    if (!buckets.spaced(q, Mq, o.spacing, reach_of(eig))) return false;
    if (!test.ball_inside(q, eig.operatorInverseSqrt(), o.boundary_gap)) return false;
    buckets.add(q, Mq);
    active.push_back(q);
    interior.push_back(q);
    return true;
  };
  if (active.empty()) {
    // No boundary seeds: start from the deepest node.
    Eigen::Index deepest = 0;
    if (domain.size() > 0) domain.minCoeff(&deepest);
    const int d = static_cast<int>(deepest);
    try_add(domain.size() > 0 ? g.point(d % g.nx, d / g.nx) : 0.5 * (lo + hi));
  }
  // Lattices only where the metric is isotropic everywhere: above the
  // columns of a metric=bl layer they made slivers that curved badly, even
  // grown only from seeds where the metric is within 1.5:1
  // (ellipse10_bl_1e-4 could not be curved to p = 3, ellipse4_a10_bl_1e-4
  // 0.842, with Poisson-disc seeds 0.911 and 0.921; docs/voronoi.md).
  if (o.interior == "lattice" && metric.anisotropy() <= kIsotropic) {
    // Breadth first from the seeds given: each seed throws candidates at the
    // six directions of a hexagonal lattice of unit metric edges, turned to
    // its parent's direction (its nearest seed's for the seeds given), and
    // kLatticeTries random ones in the annulus; the Poisson-disc pass below
    // then fills the gaps where lattices meet.
    std::vector<double> turn;  // each active seed's lattice direction, in M^1/2 space
    turn.reserve(active.size());
    for (const Eigen::Vector2d& p : active) {
      const Eigen::Matrix2d Mp = metric.metric_at(p);
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(Mp);
      const Eigen::Vector2d v = eig.operatorSqrt() * (buckets.nearest(p, Mp, reach_of(eig)) - p);
      turn.push_back(v.squaredNorm() > 0 ? std::atan2(v.y(), v.x()) : 0.0);
    }
    for (std::size_t head = 0; head < active.size(); ++head) {
      const Eigen::Vector2d p = active[head];
      const double base = turn[head];
      const Eigen::Matrix2d root_inv =
          Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(metric.metric_at(p)).operatorInverseSqrt();
      const auto throw_at = [&](double a, double r) {
        if (try_add(p + r * (root_inv * Eigen::Vector2d(std::cos(a), std::sin(a)))))
          turn.push_back(a);
      };
      for (int k = 0; k < 6; ++k) throw_at(base + k * M_PI / 3, kLatticeStep);
      for (int t = 0; t < kLatticeTries; ++t)
        throw_at(2 * M_PI * unit(gen), o.spacing * (1 + o.annulus * unit(gen)));
    }
  }
  while (!active.empty()) {
    const std::size_t pick = static_cast<std::size_t>(unit(gen) * active.size()) % active.size();
    const Eigen::Vector2d p = active[pick];
    // Directions in the unit ball of M(p): x = M^-1/2 (cos a, sin a).
    const Eigen::Matrix2d root_inv =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(metric.metric_at(p)).operatorInverseSqrt();
    bool placed = false;
    for (int t = 0; t < o.tries && !placed; ++t) {
      const double a = 2 * M_PI * unit(gen);
      const double r = o.spacing * (1 + o.annulus * unit(gen));
      const Eigen::Vector2d q = p + r * (root_inv * Eigen::Vector2d(std::cos(a), std::sin(a)));
      placed = try_add(q);
    }
    if (!placed) {
      active[pick] = active.back();
      active.pop_back();
    }
  }
  Eigen::Matrix2Xd out(2, static_cast<Eigen::Index>(interior.size()));
  for (std::size_t k = 0; k < interior.size(); ++k) out.col(k) = interior[k];
  return out;
}

}  // namespace homesh
