#pragma once
// The fast-marching engine's view of a VoronoiProblem: the FM-LBR stencil
// (lattice_stencil.h) each crystal uses at each grid node, the nodes whose
// stencil reaches a given node (the ones to update when it is accepted), and
// whether a straight step between two points stays inside the domain.
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

#include "voronoi/lattice_stencil.h"
#include "voronoi/voronoi_problem.h"

namespace homesh {

class StencilField {
 public:
  /// Throws homesh::Error if the domain or seed_metrics have the wrong size.
  explicit StencilField(const VoronoiProblem& problem);

  const CartesianGrid& grid() const { return grid_; }
  bool has_domain() const { return domain_.size() > 0; }
  /// A metric field that varies in space (stencils per node).
  bool varying() const { return !rev_start_.empty(); }
  /// domain <= 0 (or no domain): a node crystals may enter.
  bool inside(int node) const { return inside_.empty() || inside_[node] != 0; }

  /// What the update of node x for crystal s from its hexagon offset k needs:
  /// offsets k - 1 and k + 1, the lengths, the sectors (k - 1, k) and (k, k + 1).
  struct Local {
    Eigen::Vector2i prev, next;
    double length = 0.0;  ///< |offset k|_M
    double euclid_prev = 0.0, euclid_next = 0.0;
    SectorConstants before, after;
  };
  Local local(int s, int x, int k) const;

  /// Calls f(x, k) for every node x whose stencil (for crystal s) has y at
  /// its hexagon offset k.
  template <class F>
  void for_each_reverse(int s, int y, F&& f) const {
    if (rev_start_.empty()) {
      const LatticeStencil& st = shared_[shared_.size() == 1 ? 0 : s];
      const int iy = y % grid_.nx, jy = y / grid_.nx;
      for (int k = 0; k < 6; ++k) {
        const int i = iy - st.offset[k].x(), j = jy - st.offset[k].y();
        if (i >= 0 && j >= 0 && i < grid_.nx && j < grid_.ny) f(grid_.index(i, j), k);
      }
      return;
    }
    for (int r = rev_start_[y]; r < rev_start_[y + 1]; ++r) f(rev_[r] >> 3, rev_[r] & 7);
  }

  /// Euclidean length of hexagon offset k of crystal s at node x.
  double euclid(int s, int x, int k) const {
    if (rev_start_.empty()) return shared_[shared_.size() == 1 ? 0 : s].euclid[k];
    return offset(x, k).cast<double>().cwiseProduct(Eigen::Vector2d(grid_.dx, grid_.dy)).norm();
  }

  /// Whether the segment between nodes x and z (Euclidean length euclid)
  /// stays in the domain: both ends are clear of the boundary by the sum of
  /// their distances to it, or visible(x, z).
  bool passable(int x, int z, double euclid) const;
  /// Whether the segment pq stays in the domain, by sphere tracing the
  /// domain's distance (bilinear between nodes) from p to q in steps of at
  /// least ds / 2; the first and last ds are not tested (a seed may sit on
  /// the boundary).
  bool visible(const Eigen::Vector2d& p, const Eigen::Vector2d& q) const;
  /// The domain's level set at p, bilinear between nodes (0 without a domain).
  double domain_at(const Eigen::Vector2d& p) const;
  /// The metric crystal s grows in at point p.
  Eigen::Matrix2d metric(int s, const Eigen::Vector2d& p) const;
  /// The metric crystal s grows in at node x.
  const Eigen::Matrix2d& node_metric(int s, int x) const {
    if (varying()) return node_[x].M;
    return seed_metrics_.empty() ? metric_.metric(0) : seed_metrics_[s];
  }

 private:
  Eigen::Vector2i offset(int x, int k) const { return hexagon_offset(node_[x].base, k); }

  CartesianGrid grid_;
  Eigen::VectorXd domain_;
  std::vector<std::uint8_t> inside_;
  MetricField metric_;
  std::vector<Eigen::Matrix2d> seed_metrics_;
  std::vector<LatticeStencil> shared_;  ///< one, or one per crystal
  /// Metric field: metric and superbase at each node (side by side: one
  /// cache line per update), reverse stencils as x * 8 + k, CSR by the node
  /// reached.
  struct NodeStencil {
    Eigen::Matrix2d M;
    Superbase base;
  };
  std::vector<NodeStencil> node_;
  std::vector<int> rev_start_, rev_;
};

}  // namespace homesh
