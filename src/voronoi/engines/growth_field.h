#pragma once
// What the level-set engine needs at each node of the fine grid, computed once
// per problem: the Shepard stencil into the coarse metric grid (Section 2.4)
// and the domain's boundary crystal (Section 2.6).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "voronoi/engines/voronoi_problem.h"

namespace homesh {

class GrowthField {
 public:
  /// Where a node sits with respect to the domain.
  enum Zone : std::uint8_t {
    inside,   ///< domain <= 0: grown into and labelled
    contact,  ///< 0 < domain <= ds: the boundary crystal's first cell
    outside,  ///< beyond: never updated
  };

  /// Throws homesh::Error if the domain has the wrong size.
  explicit GrowthField(const VoronoiProblem& problem);

  const CartesianGrid& grid() const { return grid_; }
  const MetricField& metric() const { return metric_; }
  bool has_domain() const { return domain_.size() > 0; }
  Contact contact_kind() const { return contact_; }
  Zone zone(int node) const { return zone_.empty() ? inside : static_cast<Zone>(zone_[node]); }
  /// The domain level set at a node (0 without a domain).
  double domain(int node) const { return has_domain() ? domain_(node) : 0.0; }
  /// Outward unit normal of the domain, N_b of Eq 2.13 (contact nodes only).
  const Eigen::Vector2d& boundary_normal(int node) const { return normal_[node]; }
  /// Shepard speed of the metric field at a fine node for unit normal N.
  double speed(int node, const Eigen::Vector2d& N) const;
  int inside_count() const { return inside_count_; }

 private:
  CartesianGrid grid_;
  MetricField metric_;
  Contact contact_;
  Eigen::VectorXd domain_;
  std::vector<std::uint8_t> zone_;
  std::vector<Eigen::Vector2d> normal_;
  std::vector<ShepardStencil> stencil_;  ///< none if the metric is uniform
  int inside_count_ = 0;
};

}  // namespace homesh
