#include "voronoi/dual/conforming_dual.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/error.h"
#include "voronoi/dual/cgal_constrained_delaunay.h"
#include "voronoi/grid/orient2d.h"

namespace homesh {
namespace {

using Pair = std::array<int, 2>;
using Triple = std::array<int, 3>;

Pair key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// Segments between seeds, bucketed by their bounding boxes for crossing
// queries.
class SegmentGrid {
 public:
  SegmentGrid(const Eigen::Matrix2Xd& seeds, const std::vector<Pair>& segments)
      : seeds_(seeds), segments_(segments) {
    lo_ = seeds.rowwise().minCoeff();
    const Eigen::Vector2d hi = seeds.rowwise().maxCoeff();
    double mean = 0.0;
    for (const auto& [a, b] : segments) mean += (seeds.col(a) - seeds.col(b)).norm();
    mean = segments.empty() ? 1.0 : mean / segments.size();
    cell_ = std::max({mean, (hi - lo_).maxCoeff() / 1024, 1e-300});
    nx_ = static_cast<int>((hi.x() - lo_.x()) / cell_) + 1;
    ny_ = static_cast<int>((hi.y() - lo_.y()) / cell_) + 1;
    cells_.resize(static_cast<std::size_t>(nx_) * ny_);
    for (int s = 0; s < static_cast<int>(segments.size()); ++s)
      visit(segments[s][0], segments[s][1], [&](std::vector<int>& c) { c.push_back(s); });
  }

  // Indices of the segments that cross a-b at a point inside both (not at a
  // shared end).
  std::vector<int> crossing(int a, int b) {
    std::vector<int> out;
    visit(a, b, [&](std::vector<int>& c) {
      for (const int s : c)
        if (crosses(a, b, segments_[s][0], segments_[s][1])) out.push_back(s);
    });
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

 private:
  template <class F>
  void visit(int a, int b, F&& f) {
    const Eigen::Vector2d p = seeds_.col(a), q = seeds_.col(b);
    const auto cx = [&](double x) {
      return std::clamp(static_cast<int>((x - lo_.x()) / cell_), 0, nx_ - 1);
    };
    const auto cy = [&](double y) {
      return std::clamp(static_cast<int>((y - lo_.y()) / cell_), 0, ny_ - 1);
    };
    for (int j = cy(std::min(p.y(), q.y())); j <= cy(std::max(p.y(), q.y())); ++j)
      for (int i = cx(std::min(p.x(), q.x())); i <= cx(std::max(p.x(), q.x())); ++i)
        f(cells_[i + static_cast<std::size_t>(nx_) * j]);
  }
  bool crosses(int a, int b, int c, int d) const {
    if (a == c || a == d || b == c || b == d) return false;
    const Eigen::Vector2d pa = seeds_.col(a), pb = seeds_.col(b);
    const Eigen::Vector2d pc = seeds_.col(c), pd = seeds_.col(d);
    return orient2d(pa, pb, pc) * orient2d(pa, pb, pd) < 0 &&
           orient2d(pc, pd, pa) * orient2d(pc, pd, pb) < 0;
  }

  const Eigen::Matrix2Xd& seeds_;
  std::vector<Pair> segments_;
  Eigen::Vector2d lo_;
  double cell_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> cells_;
};

bool inside_polygon(const Eigen::Matrix2Xd& seeds, const std::vector<Pair>& boundary,
                    const Eigen::Vector2d& p) {
  bool inside = false;
  for (const auto& [i, j] : boundary) {
    const Eigen::Vector2d a = seeds.col(i), b = seeds.col(j);
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
  }
  return inside;
}

Triple rotated(Triple t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

}  // namespace

ConformingTriangulation conforming_triangulation(const Eigen::Matrix2Xd& seeds,
                                                 const std::vector<Pair>& boundary,
                                                 const std::vector<Triple>& dual) {
  ConformingTriangulation out;
  SegmentGrid walls(seeds, boundary);
  for (const auto& [a, b] : boundary)
    if (!walls.crossing(a, b).empty()) throw Error("the boundary polygon crosses itself");
  std::set<Pair> forward(boundary.begin(), boundary.end());

  std::set<Pair> in_dual;
  std::vector<Triple> kept;
  for (const Triple& t : dual) {
    for (int k = 0; k < 3; ++k) in_dual.insert(key(t[k], t[(k + 1) % 3]));
    const Eigen::Vector2d a = seeds.col(t[0]), b = seeds.col(t[1]), c = seeds.col(t[2]);
    if (orient2d(a, b, c) <= 0 || !inside_polygon(seeds, boundary, (a + b + c) / 3)) continue;
    bool ok = true;
    for (int k = 0; k < 3 && ok; ++k) {
      const int p = t[k], q = t[(k + 1) % 3];
      ok = !forward.count({q, p}) && walls.crossing(p, q).empty();
    }
    if (ok) kept.push_back(t);
  }
  for (const Pair& e : forward) out.boundary_missed += !in_dual.count(key(e[0], e[1]));

  // No directed edge twice (overlapping triangles), no kept edges crossing.
  std::map<Pair, int> directed;
  for (const Triple& t : kept)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  std::vector<char> drop(kept.size(), 0);
  std::map<Pair, std::vector<int>> owners;
  for (std::size_t f = 0; f < kept.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int p = kept[f][k], q = kept[f][(k + 1) % 3];
      if (directed[{p, q}] > 1) drop[f] = 1;
      owners[key(p, q)].push_back(static_cast<int>(f));
    }
  std::vector<Pair> edges;
  for (const auto& [e, f] : owners) edges.push_back(e);
  SegmentGrid inner(seeds, edges);
  for (const Pair& e : edges)
    for (const int other : inner.crossing(e[0], e[1])) {
      for (const int f : owners[e]) drop[f] = 1;
      for (const int f : owners[edges[other]]) drop[f] = 1;
    }
  std::set<Pair> constraints;
  std::set<Triple> good;
  for (std::size_t f = 0; f < kept.size(); ++f) {
    if (drop[f]) continue;
    good.insert(rotated(kept[f]));
    for (int k = 0; k < 3; ++k) {
      const Pair e = key(kept[f][k], kept[f][(k + 1) % 3]);
      if (!forward.count(e) && !forward.count({e[1], e[0]})) constraints.insert(e);
    }
  }
  out.triangles = cgal_constrained_triangles(
      seeds, boundary, std::vector<Pair>(constraints.begin(), constraints.end()));
  for (const Triple& t : out.triangles) out.from_dual += good.count(t) > 0;
  out.filled = static_cast<int>(out.triangles.size()) - out.from_dual;
  out.dual_dropped = static_cast<int>(dual.size()) - out.from_dual;
  return out;
}

}  // namespace homesh
