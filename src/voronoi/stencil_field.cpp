#include "voronoi/stencil_field.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace homesh {

StencilField::StencilField(const VoronoiProblem& problem)
    : grid_(problem.grid),
      domain_(problem.domain),
      metric_(problem.metric),
      seed_metrics_(problem.seed_metrics) {
  check_domain_size(problem);
  const CartesianGrid& g = grid_;
  const int n = g.node_count();
  if (has_domain()) {
    inside_.resize(n);
    for (int k = 0; k < n; ++k) inside_[k] = domain_(k) <= 0.0;
  }
  const int S = static_cast<int>(problem.seeds.cols());
  if (!seed_metrics_.empty()) {
    if (static_cast<int>(seed_metrics_.size()) != S)
      throw Error("voronoi: " + std::to_string(seed_metrics_.size()) + " seed metrics for " +
                  std::to_string(S) + " seeds");
    for (const Eigen::Matrix2d& M : seed_metrics_)
      shared_.push_back(lattice_stencil(M, g.dx, g.dy));
    return;
  }
  if (metric_.uniform()) {
    shared_.push_back(lattice_stencil(metric_.metric(0), g.dx, g.dy));
    return;
  }
  const Eigen::Matrix2d scale = Eigen::Vector2d(g.dx, g.dy).asDiagonal();
  node_.resize(n);
  rev_start_.assign(n + 1, 0);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const int x = g.index(i, j);
      node_[x].M = metric_.metric_at(g.point(i, j));
      node_[x].base = obtuse_superbase(scale * node_[x].M * scale);
    }
  // Reverse stencils: count, then fill, by the node each offset reaches.
  const auto reach = [&](int x, int k) {
    const Eigen::Vector2i o = offset(x, k);
    const int i = x % g.nx + o.x(), j = x / g.nx + o.y();
    return (i >= 0 && j >= 0 && i < g.nx && j < g.ny) ? g.index(i, j) : -1;
  };
  for (int x = 0; x < n; ++x)
    for (int k = 0; k < 6; ++k)
      if (const int y = reach(x, k); y >= 0) ++rev_start_[y + 1];
  for (int y = 0; y < n; ++y) rev_start_[y + 1] += rev_start_[y];
  rev_.resize(rev_start_[n]);
  std::vector<int> fill(rev_start_.begin(), rev_start_.end() - 1);
  for (int x = 0; x < n; ++x)
    for (int k = 0; k < 6; ++k)
      if (const int y = reach(x, k); y >= 0) rev_[fill[y]++] = x * 8 + k;
}

StencilField::Local StencilField::local(int s, int x, int k) const {
  const int kp = (k + 5) % 6, kn = (k + 1) % 6;
  Local out;
  if (rev_start_.empty()) {
    const LatticeStencil& st = shared_[shared_.size() == 1 ? 0 : s];
    out.prev = st.offset[kp];
    out.next = st.offset[kn];
    out.length = st.length[k];
    out.euclid_prev = st.euclid[kp];
    out.euclid_next = st.euclid[kn];
    out.before = st.sector[kp];
    out.after = st.sector[k];
    return out;
  }
  const Eigen::Vector2d h(grid_.dx, grid_.dy);
  const Eigen::Matrix2d& M = node_[x].M;
  out.prev = offset(x, kp);
  out.next = offset(x, kn);
  const Eigen::Vector2d U = offset(x, k).cast<double>().cwiseProduct(h);
  const Eigen::Vector2d P = out.prev.cast<double>().cwiseProduct(h);
  const Eigen::Vector2d N = out.next.cast<double>().cwiseProduct(h);
  out.length = std::sqrt(U.dot(M * U));
  out.euclid_prev = P.norm();
  out.euclid_next = N.norm();
  out.before = sector_constants(M, P, U);
  out.after = sector_constants(M, U, N);
  return out;
}

double StencilField::domain_at(const Eigen::Vector2d& p) const {
  return has_domain() ? bilinear_at(grid_, domain_, p) : 0.0;
}

bool StencilField::passable(int x, int z, double euclid) const {
  if (!has_domain() || -domain_(x) - domain_(z) >= euclid) return true;
  const CartesianGrid& g = grid_;
  return visible(g.point(x % g.nx, x / g.nx), g.point(z % g.nx, z / g.nx));
}

bool StencilField::visible(const Eigen::Vector2d& p, const Eigen::Vector2d& q) const {
  if (!has_domain()) return true;
  const double length = (q - p).norm(), ds = grid_.ds();
  for (double s = ds; s < length - ds;) {
    const double d = domain_at(p + (q - p) * (s / length));
    if (d > 0.0) return false;
    s += std::max(-d, 0.5 * ds);
  }
  return true;
}

Eigen::Matrix2d StencilField::metric(int s, const Eigen::Vector2d& p) const {
  return seed_metrics_.empty() ? metric_.metric_at(p) : seed_metrics_[s];
}

}  // namespace homesh
