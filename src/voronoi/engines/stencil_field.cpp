#include "voronoi/engines/stencil_field.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>

#include "core/error.h"

namespace homesh {

bool StencilField::built_for(const VoronoiProblem& p) const {
  const CartesianGrid& g = p.grid;
  return g.origin == grid_.origin && g.dx == grid_.dx && g.dy == grid_.dy && g.nx == grid_.nx &&
         g.ny == grid_.ny && p.domain.size() == domain_.size() &&
         (p.domain.data() == domain_.data() || p.domain == domain_) && p.metric == metric_ &&
         p.seed_metrics == seed_metrics_;
}

StencilField::StencilField(const VoronoiProblem& problem)
    : grid_(problem.grid),
      domain_(problem.domain),
      metric_(problem.metric),
      seed_metrics_(problem.seed_metrics) {
  check_domain_size(problem);
  const CartesianGrid& g = grid_;
  const int n = g.node_count();
  if (has_domain()) {
    flags_.resize(n);
    for (int k = 0; k < n; ++k) flags_[k] = domain_(k) <= 0.0 ? kInside : 0;
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
  // The superbases alone as well, 8 bytes a node: the passes below read
  // only them (a quarter of the stencils' memory traffic).
  HugeVector<std::uint64_t> base(n);
  for (int j = 0, x = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i, ++x) {
      const Eigen::Matrix2d M = metric_.metric_at(g.point(i, j));
      node_[x] =
          i == 0 ? lattice_stencil(M, g.dx, g.dy) : lattice_stencil(M, g.dx, g.dy, node_[x - 1]);
      std::memcpy(&base[x], node_[x].e, sizeof base[x]);
    }
  const auto offsets = [](std::uint64_t b, Eigen::Vector2i o[6]) {
    std::int16_t e[4];
    std::memcpy(e, &b, sizeof e);
    const Superbase sb{{e[0], e[1]}, {e[2], e[3]}};
    for (int k = 0; k < 6; ++k) o[k] = hexagon_offset(sb, k);
  };
  // Reverse stencils. Node y is regular if every node reaching it has y's
  // superbase (then x = y - offset_y(k) reaches it at offset k) and every
  // such candidate in the grid does: its reverse stencil is its own hexagon
  // reflected. Only the others get a list (CSR, by the node reached), of
  // its candidates of its superbase and the nodes of another superbase
  // reaching it (`cross`: (y, x * 8 + k), in increasing x).
  irregular_.assign(n, 0);
  std::vector<std::pair<int, int>> cross;
  Eigen::Vector2i o[6];
  for (int j = 0, x = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i, ++x) {
      offsets(base[x], o);
      for (int k = 0; k < 6; ++k) {
        const int a = i + o[k].x(), c = j + o[k].y();
        if (a < 0 || c < 0 || a >= g.nx || c >= g.ny) continue;
        const int y = g.index(a, c);
        if (base[y] == base[x]) continue;
        irregular_[y] = 1;
        cross.emplace_back(y, x * 8 + k);
      }
    }
  const auto for_each_candidate = [&](int y, auto&& f) {
    offsets(base[y], o);
    const int i = y % g.nx, j = y / g.nx;
    for (int k = 0; k < 6; ++k) {
      const int a = i - o[k].x(), c = j - o[k].y();
      if (a >= 0 && c >= 0 && a < g.nx && c < g.ny) f(g.index(a, c), k);
    }
  };
  for (int y = 0; y < n; ++y)
    if (!irregular_[y])
      for_each_candidate(y, [&](int x, int) { irregular_[y] |= base[x] != base[y]; });
  std::stable_sort(cross.begin(), cross.end(),
                   [](const auto& l, const auto& r) { return l.first < r.first; });
  rev_start_.assign(n + 1, 0);
  auto next_cross = cross.begin();
  std::vector<int> list;
  for (int y = 0; y < n; ++y) {
    rev_start_[y + 1] = rev_start_[y];
    if (!irregular_[y]) continue;
    list.clear();
    for_each_candidate(y, [&](int x, int k) {
      if (base[x] == base[y]) list.push_back(x * 8 + k);
    });
    for (; next_cross != cross.end() && next_cross->first == y; ++next_cross)
      list.push_back(next_cross->second);
    std::sort(list.begin(), list.end());
    rev_.insert(rev_.end(), list.begin(), list.end());
    rev_start_[y + 1] = static_cast<int>(rev_.size());
  }
  mask_steps();
}

void StencilField::mask_steps() {
  if (!has_domain()) return;
  const CartesianGrid& g = grid_;
  for (int j = 0, x = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i, ++x) {
      if (!(flags_[x] & kInside)) continue;
      const LatticeStencil& st = stencil(0, x);
      // Far from the boundary every step lies in the disc of x's clearance.
      double reach2 = 0.0;
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector2i o = st.offset(k);
        reach2 = std::max(reach2, o.x() * o.x() * g.dx * g.dx + o.y() * o.y() * g.dy * g.dy);
      }
      const double cx = clearance(x);
      if (cx >= 0.0 && cx * cx >= reach2) {
        flags_[x] |= 0x3f;
        continue;
      }
      for (int k = 0; k < 6; ++k) {
        const Eigen::Vector2i o = st.offset(k);
        const int a = i + o.x(), c = j + o.y();
        if (a >= 0 && c >= 0 && a < g.nx && c < g.ny && passable(x, g.index(a, c)))
          flags_[x] |= static_cast<std::uint8_t>(1 << k);
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
