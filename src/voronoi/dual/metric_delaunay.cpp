#include "voronoi/dual/metric_delaunay.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "core/mesh.h"
#include "layers/edge_flip_sweep.h"

namespace homesh {
namespace {

double orient(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

}  // namespace

// The in-circle determinant (Guibas and Stolfi 1985) of the mapped points.
bool in_metric_circle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                      const Eigen::Vector2d& d, const Eigen::Matrix2d& M) {
  const Eigen::Matrix2d L = M.llt().matrixU();  // M = L^T L, det L > 0
  const Eigen::Vector2d p = L * (a - d), q = L * (b - d), r = L * (c - d);
  const double pp = p.squaredNorm(), qq = q.squaredNorm(), rr = r.squaredNorm();
  const double det = pp * (q.x() * r.y() - q.y() * r.x()) - qq * (p.x() * r.y() - p.y() * r.x()) +
                     rr * (p.x() * q.y() - p.y() * q.x());
  const double scale = std::max({pp, qq, rr});
  return det > 1e-12 * scale * scale;
}

// Lawson's flips in the metric of each quad (Borouchaki et al. 1997).
MetricDelaunay metric_delaunay_flips(const Eigen::Matrix2Xd& x,
                                     std::vector<std::array<int, 3>>& triangles,
                                     const std::vector<std::array<int, 2>>& segments,
                                     const MetricField& metric, int max_sweeps) {
  Mesh m;
  m.order = 1;
  m.x = x;
  m.tri.resize(3, static_cast<Eigen::Index>(triangles.size()));
  for (std::size_t t = 0; t < triangles.size(); ++t)
    m.tri.col(t) << triangles[t][0], triangles[t][1], triangles[t][2];
  m.tri_entity.assign(triangles.size(), 0);
  m.line.resize(2, static_cast<Eigen::Index>(segments.size()));
  for (std::size_t s = 0; s < segments.size(); ++s) m.line.col(s) << segments[s][0], segments[s][1];
  // (a, b, c) and (b, a, d): flip to (c, d, b), (d, c, a) where d is inside
  // the circle of (a, b, c) in the quad's metric and both new ones are
  // counter-clockwise.
  const auto flips_to_delaunay = [&](int a, int b, int c, int d) {
    const Eigen::Vector2d A = x.col(a), B = x.col(b), C = x.col(c), D = x.col(d);
    if (!(orient(C, D, B) > 0 && orient(D, C, A) > 0)) return false;
    return in_metric_circle(A, B, C, D, metric.metric_at(0.25 * (A + B + C + D)));
  };
  MetricDelaunay out;
  const std::vector<int> all = all_triangles(m);
  out.flips = flip_edges_where(m, all, flips_to_delaunay, max_sweeps);
  // What is left: edges not locally Delaunay (whether or not they can flip),
  // as the corner triples of their two triangles, then marked in one pass.
  std::vector<std::array<int, 3>> bad_corners;
  flip_edges_where(
      m, all,
      [&](int a, int b, int c, int d) {
        const Eigen::Vector2d A = x.col(a), B = x.col(b), C = x.col(c), D = x.col(d);
        if (in_metric_circle(A, B, C, D, metric.metric_at(0.25 * (A + B + C + D))))
          for (const std::array<int, 3>& t : {std::array<int, 3>{a, b, c}, {a, b, d}}) {
            bad_corners.push_back(t);
            std::sort(bad_corners.back().begin(), bad_corners.back().end());
          }
        return false;
      },
      1);
  std::sort(bad_corners.begin(), bad_corners.end());
  std::vector<char> bad(triangles.size(), 0);
  for (Eigen::Index t = 0; t < m.tri.cols(); ++t) {
    std::array<int, 3> c = {m.tri(0, t), m.tri(1, t), m.tri(2, t)};
    std::sort(c.begin(), c.end());
    bad[t] = std::binary_search(bad_corners.begin(), bad_corners.end(), c);
  }
  out.not_delaunay = std::count(bad.begin(), bad.end(), 1);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    triangles[t] = {m.tri(0, t), m.tri(1, t), m.tri(2, t)};
  return out;
}

}  // namespace homesh
