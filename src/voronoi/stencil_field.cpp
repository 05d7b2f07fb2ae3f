#include "voronoi/stencil_field.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
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
    for (int k = 0; k < n; ++k) inside_[k] = domain_(k) <= 0.0 ? kInside : 0;
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
    mask_steps();
    return;
  }
  node_.resize(n);
  rev_start_.assign(n + 1, 0);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      node_[g.index(i, j)] = lattice_stencil(metric_.metric_at(g.point(i, j)), g.dx, g.dy);
  // Reverse stencils. Node y is regular if every node reaching it has y's
  // superbase (then x = y - offset_y(k) reaches it at offset k) and every
  // such candidate in the grid does: its reverse stencil is its own hexagon
  // reflected. Only the others get a list (CSR, by the node reached).
  const auto for_each_reach = [&](auto&& f) {
    for (int j = 0, x = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i, ++x) {
        const Superbase b = node_[x].base();
        const Eigen::Vector2i o[6] = {b.e1, b.e1 + b.e2, b.e2, -b.e1, -b.e1 - b.e2, -b.e2};
        for (int k = 0; k < 6; ++k) {
          const int a = i + o[k].x(), c = j + o[k].y();
          if (a >= 0 && c >= 0 && a < g.nx && c < g.ny) f(x, k, g.index(a, c));
        }
      }
  };
  const auto same_base = [&](int x, int y) {
    std::uint64_t a, b;  // the four offsets at once (std::equal calls memcmp)
    std::memcpy(&a, node_[x].e, sizeof a);
    std::memcpy(&b, node_[y].e, sizeof b);
    return a == b;
  };
  irregular_.assign(n, 0);
  std::vector<int> reached(n, 0);
  for_each_reach([&](int x, int, int y) {
    ++reached[y];
    if (!same_base(x, y)) irregular_[y] = 1;
  });
  for (int j = 0, y = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i, ++y) {
      if (irregular_[y]) continue;
      int candidates = 0;
      for (int k = 0; k < 6; ++k) {
        const Eigen::Vector2i o = node_[y].offset(k);
        const int a = i - o.x(), c = j - o.y();
        candidates += a >= 0 && c >= 0 && a < g.nx && c < g.ny;
      }
      irregular_[y] = reached[y] != candidates;
    }
  for (int y = 0; y < n; ++y) rev_start_[y + 1] = rev_start_[y] + (irregular_[y] ? reached[y] : 0);
  rev_.resize(rev_start_[n]);
  std::vector<int> fill(rev_start_.begin(), rev_start_.end() - 1);
  for_each_reach([&](int x, int k, int y) {
    if (irregular_[y]) rev_[fill[y]++] = x * 8 + k;
  });
  mask_steps();
}

void StencilField::mask_steps() {
  if (!has_domain()) return;
  const CartesianGrid& g = grid_;
  for (int j = 0, x = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i, ++x) {
      if (!(inside_[x] & kInside)) continue;
      const LatticeStencil& st = stencil(0, x);
      // Far from the boundary every step lies in the disc of x's clearance.
      double reach2 = 0.0;
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector2i o = st.offset(k);
        reach2 = std::max(reach2, o.x() * o.x() * g.dx * g.dx + o.y() * o.y() * g.dy * g.dy);
      }
      const double cx = clearance(x);
      if (cx >= 0.0 && cx * cx >= reach2) {
        inside_[x] |= 0x3f;
        continue;
      }
      for (int k = 0; k < 6; ++k) {
        const Eigen::Vector2i o = st.offset(k);
        const int a = i + o.x(), c = j + o.y();
        if (a >= 0 && c >= 0 && a < g.nx && c < g.ny && passable(x, g.index(a, c)))
          inside_[x] |= static_cast<std::uint8_t>(1 << k);
      }
    }
  stepped_ = true;
}

double StencilField::domain_at(const Eigen::Vector2d& p) const {
  return has_domain() ? bilinear_at(grid_, domain_, p) : 0.0;
}

bool StencilField::passable(int x, int z) const {
  if (!has_domain()) return true;
  const CartesianGrid& g = grid_;
  const Eigen::Vector2d p = g.point(x % g.nx, x / g.nx), q = g.point(z % g.nx, z / g.nx);
  return segment_clear(p, clearance(x), q, clearance(z), (q - p).norm());
}

bool StencilField::segment_clear(const Eigen::Vector2d& p, double cp, const Eigen::Vector2d& q,
                                 double cq, double length) const {
  return cp + cq >= length || visible(p, q);
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
