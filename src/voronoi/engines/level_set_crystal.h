#pragma once
// One crystal of the level-set engine: its level set phi_s (crystal =
// {phi_s <= 0}) and collision sensor beta_s (Eq 2.1), stored on the box of grid
// nodes around it and advanced by the first-order upwind scheme of
// Eqs 2.2-2.5 with the speed of Eq 2.8 (convention of metric_field.h) or the
// dry-contact speed of Eq 2.13.
//
// The level set starts as the metric distance to the seed minus the radius,
// phi_s = |x - p_s|_{M_s} - r_s (the exact crystal at time r_s), and is stored
// only on the nodes within `band` cells of the crystal's bounding box. A node
// entering the box takes the start value at the current time t,
// |x - p_s|_{M_s} - max(t, r_s) (exact in a constant metric), plus the lag of
// the computed solution behind it at the nearest node of the old box, so that
// the stored values stay consistent. Nodes more than `band` cells of metric
// length inside the front are advanced at the unit rate of a metric distance
// (F |grad phi| = 1): upwind information only flows outward, so they cannot
// reach the front.
//
// Nodes already taken by another crystal, or closed by a collision, are not
// advanced: the crystal can only collide there (Eqs 2.10-2.11 reset it), and
// its level set would otherwise keep falling like a cone behind a frozen
// interface and surface in the gaps between other crystals.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "voronoi/engines/growth_field.h"

namespace homesh {

/// Inclusive range of grid nodes [i0, i1] x [j0, j1].
struct NodeBox {
  int i0 = 0, j0 = 0, i1 = -1, j1 = -1;
  bool contains(int i, int j) const { return i >= i0 && i <= i1 && j >= j0 && j <= j1; }
  int width() const { return i1 - i0 + 1; }
  int height() const { return j1 - j0 + 1; }
  bool empty() const { return i1 < i0 || j1 < j0; }
  /// Grows the box to hold node (i, j).
  void extend(int i, int j) {
    if (empty()) {
      *this = {i, j, i, j};
      return;
    }
    i0 = i < i0 ? i : i0;
    j0 = j < j0 ? j : j0;
    i1 = i > i1 ? i : i1;
    j1 = j > j1 ? j : j1;
  }
};

class LevelSetCrystal {
 public:
  /// The seed crystal is the ball {x : |x - seed|_M <= radius}; own: if
  /// non-null, the constant metric this crystal grows in instead of the
  /// field's.
  LevelSetCrystal(const GrowthField& field, const Eigen::Vector2d& seed, const Eigen::Matrix2d& M,
                  double radius, int band, const Eigen::Matrix2d* own);

  /// Metric radius of the seed crystal; the crystal starts growing at t = r_s.
  double birth_time() const { return r_; }
  const NodeBox& box() const { return box_; }
  /// phi_s at grid node (i, j) inside box(): current and next step.
  double phi(int i, int j) const { return phi_[local(i, j)]; }
  double next(int i, int j) const { return next_[local(i, j)]; }

  /// Values of `owner` other than crystal ids.
  static constexpr int kFree = -1;    ///< in no crystal yet
  static constexpr int kClosed = -2;  ///< a collision node in no crystal

  /// next = phi - dt beta F D (Eq 2.2) at every node of the box; next = phi
  /// where beta = 0, outside the domain's contact band, on nodes that owner
  /// (grid.node_count(): the crystal that took each node first, kFree or
  /// kClosed) neither leaves free nor gives to `self`, or if grow is false;
  /// next = phi - dt deep inside.
  void advance(double dt, bool grow, const std::vector<int>& owner, int self);
  /// Eqs 2.11-2.12 at grid node (i, j): next = phi, beta = 0.
  void freeze(int i, int j);
  /// Makes next current. newly_inside receives each grid node that entered
  /// the crystal. Then refits the box at time t. After `patience` steps
  /// since its birth with no node entering, the crystal is blocked all round
  /// and goes dormant: advance and commit do nothing from then on.
  void commit(double t, int patience, std::vector<int>& newly_inside);
  bool dormant() const { return dormant_; }

 private:
  int local(int i, int j) const { return (i - box_.i0) + box_.width() * (j - box_.j0); }
  double start_value(int i, int j, double t) const;
  double interpolate(double u, double v) const;
  double speed(int node, const Eigen::Vector2d& N) const;
  void fit_box(double t);

  const GrowthField* field_;
  Eigen::Vector2d seed_;
  Eigen::Matrix2d M_;
  Eigen::Matrix2d own_inverse_;
  bool has_own_ = false;
  double r_ = 0.0;
  int band_ = 1;
  double deep_ = 0.0;
  double cell_ = 0.0;  ///< metric length of the shortest cell step, >= ds / max F
  int idle_ = 0;
  bool dormant_ = false;
  NodeBox box_;
  NodeBox inside_;  ///< bounding box of {phi <= 0}
  std::vector<double> phi_, next_;
  std::vector<std::uint8_t> frozen_;
};

}  // namespace homesh
