#include "voronoi/grid/loop_distance.h"

#include <algorithm>
#include <cmath>

#include "core/huge_page_allocator.h"

namespace homesh {
namespace {

double segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - a - t * ab).norm();
}

// Calls f(a, b) for every edge of every loop.
template <class F>
void for_each_edge(const std::vector<Eigen::Matrix2Xd>& loops, F&& f) {
  for (const Eigen::Matrix2Xd& loop : loops)
    for (Eigen::Index k = 0; k < loop.cols(); ++k)
      f(Eigen::Vector2d(loop.col(k)), Eigen::Vector2d(loop.col((k + 1) % loop.cols())));
}

constexpr double kChordTolerance = 0.01;  // decimated polygons: within this many cells
constexpr int kChordSamples = 64;         // ... of every sample a chord skips, at most this many

// The loops with every sample dropped that a chord from the last sample kept
// passes within `tol` of (with those before it), at most kChordSamples in a
// row: the band's distances then cost per grid cell of the boundary, not per
// sample (2000 per CAD curve, where the grid may have 20 cells along it).
std::vector<Eigen::Matrix2Xd> decimated(const std::vector<Eigen::Matrix2Xd>& loops, double tol) {
  std::vector<Eigen::Matrix2Xd> out;
  for (const Eigen::Matrix2Xd& loop : loops) {
    std::vector<Eigen::Index> kept{0};
    const Eigen::Index n = loop.cols();
    for (Eigen::Index j = 2; j < n; ++j) {
      const Eigen::Index a = kept.back();
      bool close = j - a <= kChordSamples;
      for (Eigen::Index k = a + 1; close && k < j; ++k)
        close = segment_distance(loop.col(k), loop.col(a), loop.col(j)) <= tol;
      if (!close) kept.push_back(j - 1);
    }
    if (n > 1) kept.push_back(n - 1);
    out.emplace_back(loop(Eigen::all, kept));
  }
  return out;
}

}  // namespace

bool inside_loops(const std::vector<Eigen::Matrix2Xd>& loops, const Eigen::Vector2d& p) {
  bool inside = false;
  for_each_edge(loops, [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
  });
  return inside;
}

Eigen::VectorXd loop_signed_distance(const CartesianGrid& g,
                                     const std::vector<Eigen::Matrix2Xd>& loops, double band) {
  // A large field is fresh memory in huge pages (core/huge_page_allocator.h): 4 MB in
  // 4 KiB pages cost ellipse10_bl_1e-4's voronoi 13 ms of faults.
  Eigen::VectorXd dist(g.node_count());
  advise_huge_pages(dist.data(), static_cast<std::size_t>(dist.size()) * sizeof(double));
  dist.setConstant(band);
  const std::vector<Eigen::Matrix2Xd> coarse = decimated(loops, kChordTolerance * g.ds());
  const auto clamp_i = [&](double v) { return std::clamp(static_cast<int>(v), 0, g.nx - 1); };
  const auto clamp_j = [&](double v) { return std::clamp(static_cast<int>(v), 0, g.ny - 1); };
  // Crossings of each grid row with the polygon edges (half-open in y).
  std::vector<std::vector<double>> crossings(g.ny);
  for_each_edge(coarse, [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d lo = a.cwiseMin(b).array() - band, hi = a.cwiseMax(b).array() + band;
    const int i0 = clamp_i(std::floor((lo.x() - g.origin.x()) / g.dx));
    const int i1 = clamp_i(std::ceil((hi.x() - g.origin.x()) / g.dx));
    const int j0 = clamp_j(std::floor((lo.y() - g.origin.y()) / g.dy));
    const int j1 = clamp_j(std::ceil((hi.y() - g.origin.y()) / g.dy));
    for (int j = j0; j <= j1; ++j) {
      const double y = g.origin.y() + j * g.dy;
      if ((a.y() > y) != (b.y() > y))
        crossings[j].push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
      for (int i = i0; i <= i1; ++i) {
        double& d = dist(g.index(i, j));
        d = std::min(d, segment_distance(g.point(i, j), a, b));
      }
    }
  });
  for (int j = 0; j < g.ny; ++j) {
    std::vector<double>& xs = crossings[j];
    std::sort(xs.begin(), xs.end());
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      const int i0 = std::max(0, static_cast<int>(std::ceil((xs[k] - g.origin.x()) / g.dx)));
      const int i1 =
          std::min(g.nx - 1, static_cast<int>(std::floor((xs[k + 1] - g.origin.x()) / g.dx)));
      for (int i = i0; i <= i1; ++i) dist(g.index(i, j)) = -dist(g.index(i, j));
    }
  }
  return dist;
}

}  // namespace homesh
