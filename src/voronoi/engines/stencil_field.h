#pragma once
// The fast-marching engine's view of a VoronoiProblem: the FM-LBR stencil
// (lattice_stencil.h, in grid units) each crystal uses at each grid node, the
// nodes whose stencil reaches a given node (the ones to update when it is
// accepted), and whether a straight step between two points stays inside the
// domain.
//
// Three cases: one metric everywhere (one stencil), a constant metric per
// crystal (VoronoiProblem::seed_metrics: one stencil per crystal), or a metric
// field: at each node the Riemannian metric M(x) = MetricField::metric_at(x)
// (the Shepard average of the corner tensors, where the level-set engine
// averages the corner speeds instead) with its own stencil, and the reverse
// stencils stored once.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/huge_page_allocator.h"
#include "voronoi/engines/lattice_stencil.h"
#include "voronoi/engines/voronoi_problem.h"

namespace homesh {

class StencilField {
 public:
  /// Throws homesh::Error if the domain or seed_metrics have the wrong size.
  explicit StencilField(const VoronoiProblem& problem);
  /// Whether these are the stencils of `problem`: the same grid, domain,
  /// metric and seed metrics (the seeds themselves do not matter).
  bool built_for(const VoronoiProblem& problem) const;

  const CartesianGrid& grid() const { return grid_; }
  bool has_domain() const { return domain_.size() > 0; }
  /// A metric field that varies in space (stencils per node).
  bool varying() const { return !rev_start_.empty(); }
  /// domain <= 0 (or no domain): a node crystals may enter.
  bool inside(int node) const { return flags_.empty() || (flags_[node] & kInside) != 0; }

  /// The stencil crystal s uses at node x.
  const LatticeStencil& stencil(int s, int x) const {
    return varying() ? node_stencil(x) : crystal_stencil(s);
  }
  /// In a metric field (varying()): the stencil at node x.
  const LatticeStencil& node_stencil(int x) const { return node_[x]; }
  /// Otherwise: the stencil of crystal s everywhere.
  const LatticeStencil& crystal_stencil(int s) const {
    return shared_[shared_.size() == 1 ? 0 : s];
  }

  /// Calls f(x, k) for every node x whose stencil (for crystal s) has y at
  /// its hexagon offset k.
  template <class F>
  void for_each_reverse(int s, int y, F&& f) const {
    if (varying() && irregular_[y]) {
      for (int r = rev_start_[y]; r < rev_start_[y + 1]; ++r) f(rev_[r] >> 3, rev_[r] & 7);
      return;
    }
    // One stencil for all nodes, or the stencils round y are y's own: the
    // reverse stencil is y's hexagon reflected, no reverse list to load.
    const LatticeStencil& st = stencil(s, y);
    const int iy = y % grid_.nx, jy = y / grid_.nx;
    for (int k = 0; k < 6; ++k) {
      const Eigen::Vector2i o = st.offset(k);
      const int i = iy - o.x(), j = jy - o.y();
      if (i >= 0 && j >= 0 && i < grid_.nx && j < grid_.ny) f(grid_.index(i, j), k);
    }
  }

  /// The domain's level set at node x (0 without a domain): minus the
  /// distance to the boundary inside, up to the band it was computed in.
  double clearance(int x) const { return has_domain() ? -domain_(x) : kFar; }
  /// Whether the segment between nodes x and z stays in the domain.
  bool passable(int x, int z) const;
  /// Whether the step from node x (inside) to x + offset k of crystal s's
  /// stencil there (a node of the grid) stays in the domain: passable(x,
  /// that node), read from a mask per node where all crystals share the
  /// stencil at x.
  bool passable_step(int s, int x, int k) const {
    if (!stepped_) {
      const Eigen::Vector2i o = stencil(s, x).offset(k);
      return passable(x, x + o.x() + o.y() * grid_.nx);
    }
    return (flags_[x] >> k) & 1;
  }
  /// Whether the segment pq, of Euclidean length `length`, stays in the
  /// domain: the clearances cp and cq of its ends add up to its length (the
  /// level set is a distance, so the discs of those radii hold the segment),
  /// or visible(p, q).
  bool segment_clear(const Eigen::Vector2d& p, double cp, const Eigen::Vector2d& q, double cq,
                     double length) const;
  /// Whether the segment pq stays in the domain, by sphere tracing the
  /// domain's distance (bilinear between nodes) from p to q in steps of at
  /// least ds / 2; the first and last ds are not tested (a seed may sit on
  /// the boundary).
  bool visible(const Eigen::Vector2d& p, const Eigen::Vector2d& q) const;
  /// The domain's level set at p, bilinear between nodes (0 without a domain).
  double domain_at(const Eigen::Vector2d& p) const;
  /// The metric crystal s grows in at point p.
  Eigen::Matrix2d metric(int s, const Eigen::Vector2d& p) const;

 private:
  static constexpr double kFar = 1e300;
  static constexpr std::uint8_t kInside = 1 << 6;

  // The masks of passable_step (with a domain, and one stencil per node).
  void mask_steps();

  CartesianGrid grid_;
  Eigen::VectorXd domain_;
  /// Per node (with a domain): kInside, and bit k for passable_step(., x, k)
  /// if stepped_.
  HugeVector<std::uint8_t> flags_;
  bool stepped_ = false;
  MetricField metric_;
  std::vector<Eigen::Matrix2d> seed_metrics_;
  std::vector<LatticeStencil> shared_;  ///< one, or one per crystal
  /// Metric field: the stencil at each node, reverse stencils as x * 8 + k,
  /// CSR by the node reached, and whether a node's reverse stencil differs
  /// from its own hexagon reflected (only there is the CSR read).
  HugeVector<LatticeStencil> node_;
  HugeVector<int> rev_start_, rev_;
  HugeVector<std::uint8_t> irregular_;
};

}  // namespace homesh
