#include "voronoi/metric/size_metric.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <string>

#include "core/error.h"
#include "voronoi/metric/wall_layer.h"

namespace homesh {

Eigen::VectorXd mean_edge_length(const Eigen::Matrix2Xd& points, const Eigen::MatrixXi& tri) {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(points.cols());
  Eigen::VectorXd count = Eigen::VectorXd::Zero(points.cols());
  for (Eigen::Index t = 0; t < tri.cols(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = tri(k, t), b = tri((k + 1) % 3, t);
      const double l = (points.col(a) - points.col(b)).norm();
      sum(a) += l;
      sum(b) += l;
      count(a) += 1;
      count(b) += 1;
    }
  return (count.array() > 0).select(sum.array() / count.array().max(1.0), 0.0);
}

MetricField iso_metric_from_sizes(const CartesianGrid& g, const Eigen::Matrix2Xd& points,
                                  const Eigen::VectorXd& h, const Eigen::MatrixXi& tri) {
  std::vector<double> size(g.node_count(), -1.0);
  for (Eigen::Index t = 0; t < tri.cols(); ++t) {
    const Eigen::Vector2d a = points.col(tri(0, t)), b = points.col(tri(1, t)),
                          c = points.col(tri(2, t));
    const Eigen::Vector2d lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    const double det = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (det == 0.0) continue;
    const int i0 = std::max(0, static_cast<int>(std::ceil((lo.x() - g.origin.x()) / g.dx)));
    const int i1 = std::min(g.nx - 1, static_cast<int>(std::floor((hi.x() - g.origin.x()) / g.dx)));
    const int j0 = std::max(0, static_cast<int>(std::ceil((lo.y() - g.origin.y()) / g.dy)));
    const int j1 = std::min(g.ny - 1, static_cast<int>(std::floor((hi.y() - g.origin.y()) / g.dy)));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const Eigen::Vector2d p = g.point(i, j) - a;
        const double l1 = (p.x() * (c - a).y() - p.y() * (c - a).x()) / det;
        const double l2 = ((b - a).x() * p.y() - (b - a).y() * p.x()) / det;
        const double l0 = 1 - l1 - l2;
        const double tol = -1e-12;
        if (l0 < tol || l1 < tol || l2 < tol) continue;
        size[g.index(i, j)] = l0 * h(tri(0, t)) + l1 * h(tri(1, t)) + l2 * h(tri(2, t));
      }
  }
  // Nodes in no triangle: breadth-first from the sized ones.
  std::deque<int> queue;
  for (int n = 0; n < g.node_count(); ++n)
    if (size[n] > 0.0) queue.push_back(n);
  if (queue.empty()) throw Error("iso metric: no coarse grid node lies in the reference mesh");
  while (!queue.empty()) {
    const int n = queue.front();
    queue.pop_front();
    const int i = n % g.nx, j = n / g.nx;
    for (const auto& [a, b] : {std::pair<int, int>{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}}) {
      if (a < 0 || b < 0 || a >= g.nx || b >= g.ny || size[g.index(a, b)] > 0.0) continue;
      size[g.index(a, b)] = size[n];
      queue.push_back(g.index(a, b));
    }
  }
  // 1 / h^2 in place: the field a_k I, every value the same, to the bit, as
  // that of the tensors I / h^2 (the entries 1 / h^2 and 0).
  for (double& h : size) h = 1.0 / (h * h);
  return MetricField::isotropic(g, std::move(size));
}

MetricField boundary_layer_metric(const MetricField& iso,
                                  const std::vector<Eigen::Matrix2Xd>& walls,
                                  const BoundaryLayerOptions& o) {
  if (!(o.wall_aspect >= 1.0 && std::isfinite(o.wall_aspect)))
    throw Error("boundary-layer metric: wall aspect " + std::to_string(o.wall_aspect) +
                " is not a finite number >= 1");
  if (!(o.thickness > 0.0 && std::isfinite(o.thickness)))
    throw Error("boundary-layer metric: thickness " + std::to_string(o.thickness) +
                " is not a finite number > 0");
  const CartesianGrid& g = iso.coarse();
  // Wall samples with their unit tangents, in buckets for a ring search.
  std::vector<Eigen::Vector2d> pts, tangents;
  for (const Eigen::Matrix2Xd& w : walls)
    for (Eigen::Index k = 0; k < w.cols(); ++k) {
      const Eigen::Index a = std::max<Eigen::Index>(k - 1, 0);
      const Eigen::Index b = std::min<Eigen::Index>(k + 1, w.cols() - 1);
      const Eigen::Vector2d t = w.col(b) - w.col(a);
      if (t.norm() == 0.0) continue;
      pts.push_back(w.col(k));
      tangents.push_back(t.normalized());
    }
  // Nearest wall sample of every coarse node: a Dijkstra over the 8
  // neighbours that hands on the nearest sample found (Danielsson's vector
  // distance transform; exact but for rare ties between distant samples).
  std::vector<double> dist(g.node_count(), std::numeric_limits<double>::infinity());
  std::vector<int> nearest(g.node_count(), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  const auto offer = [&](int n, int k) {
    const Eigen::Vector2d x = g.point(n % g.nx, n / g.nx);
    const double d = (pts[k] - x).norm();
    if (d >= dist[n]) return;
    dist[n] = d;
    nearest[n] = k;
    heap.push({d, n});
  };
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const int i = std::clamp(static_cast<int>((pts[k].x() - g.origin.x()) / g.dx), 0, g.nx - 2);
    const int j = std::clamp(static_cast<int>((pts[k].y() - g.origin.y()) / g.dy), 0, g.ny - 2);
    for (int b = j; b <= j + 1; ++b)
      for (int a = i; a <= i + 1; ++a) offer(g.index(a, b), static_cast<int>(k));
  }
  while (!heap.empty()) {
    const auto [d, n] = heap.top();
    heap.pop();
    if (d > dist[n]) continue;
    const int i = n % g.nx, j = n / g.nx;
    for (int b = std::max(j - 1, 0); b <= std::min(j + 1, g.ny - 1); ++b)
      for (int a = std::max(i - 1, 0); a <= std::min(i + 1, g.nx - 1); ++a)
        offer(g.index(a, b), nearest[n]);
  }
  std::vector<Eigen::Matrix2d> M(g.node_count());
  for (int n = 0; n < g.node_count(); ++n) {
    M[n] = iso.metric(n);
    const double h = 1.0 / std::sqrt(iso.metric(n)(0, 0));
    if (nearest[n] < 0 || dist[n] >= o.thickness * h) continue;
    const double hn =
        h * (1.0 / o.wall_aspect + (1.0 - 1.0 / o.wall_aspect) * dist[n] / (o.thickness * h));
    const Eigen::Vector2d t = tangents[nearest[n]];
    M[n] = metric_from_axes(std::atan2(t.y(), t.x()), h, hn);
  }
  // The same tensors at any point from its own distance (wall_layer.h): the
  // coarse nodes lie too far apart for the first cells of a 100:1 layer.
  MetricField out(g, std::move(M));
  if (pts.empty()) return out;
  double spacing = 0;
  for (const Eigen::Matrix2Xd& w : walls)
    for (Eigen::Index k = 0; k + 1 < w.cols(); ++k)
      spacing = std::max(spacing, (w.col(k + 1) - w.col(k)).norm());
  return out.with_layer(std::make_shared<const WallLayer>(iso, walls, o.wall_aspect, o.thickness,
                                                          std::move(dist), 0.5 * spacing));
}

}  // namespace homesh
