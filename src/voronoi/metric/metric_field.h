#pragma once
// The metric field that steers the growth of the crystals (thesis Section 2.4,
// Eqs 2.6-2.8) and the speed it gives a front.
//
// Convention (settled by the analytic test in tests/voronoi): M measures
// lengths, |v|_M = sqrt(v^T M v); its unit ball {x : x^T M x <= 1} is the
// ellipse of semi-axes 1/sqrt(lambda_i) along the eigenvectors of M (Eq 2.7).
// A crystal growing from a point p in a constant M is, at time t, the ball
// {x : (x - p)^T M (x - p) <= t^2}, so time is metric distance and the crystals
// meet on the metric bisectors. That ball's boundary moves along its unit
// normal N at the ball's support function
//
//   F(N) = sqrt(N^T M^-1 N),
//
// which is the speed used here. Eq 2.8 of the thesis reads F ~ sqrt(N^T M N):
// taken literally it grows the same ellipse turned by 90 degrees (for 2 by 2
// SPD M, M^-1 = R90 M R90^T / det M), i.e. it holds with M read as the inverse
// of the metric whose ellipse is drawn with semi-axes 1/sqrt(lambda_i).
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <vector>

#include "voronoi/grid/cartesian_grid.h"

namespace homesh {

class WallLayer;  // voronoi/metric/wall_layer.h

/// Eq 2.7: M = R^T diag(1/h1^2, 1/h2^2) R, R = [cos t, sin t; -sin t, cos t],
/// whose unit ball is the ellipse with semi-axis h1 along the direction at angle
/// t from the x-axis and semi-axis h2 across it (h1 > h2: t is the angle of the
/// major axis). Throws homesh::Error unless h1, h2 > 0.
Eigen::Matrix2d metric_from_axes(double theta, double h1, double h2);

/// Normal speed of a front with unit normal N in the constant metric whose
/// inverse is Minv: sqrt(N^T Minv N) (see the convention above).
inline double metric_speed(const Eigen::Matrix2d& Minv, const Eigen::Vector2d& N) {
  return std::sqrt(N.dot(Minv * N));
}

/// Shepard (inverse-distance, power 2) weights of the 4 corners of the coarse
/// cell that holds a point: w_k = d_k^-2 / sum_l d_l^-2, or weight 1 on a corner
/// the point coincides with. Points outside the coarse grid are clamped to it.
struct ShepardStencil {
  std::array<int, 4> node{};  ///< coarse node indices
  std::array<double, 4> w{};  ///< weights, sum 1
};

/// A metric tensor at each node of a coarse Cartesian grid (Section 2.4,
/// Fig 2.1a). The speed at a point is the Shepard average of the speeds
/// evaluated with the metrics of the 4 corners of its coarse cell.
class MetricField {
 public:
  /// M: one symmetric positive definite matrix per coarse node (index
  /// coarse.index(i, j)). Throws homesh::Error if the count is wrong or a
  /// matrix is not SPD.
  MetricField(const CartesianGrid& coarse, std::vector<Eigen::Matrix2d> M);
  /// The isotropic field a_k I at coarse node k, kept as the numbers a_k (a
  /// quarter of the tensors' memory; every value the same, to the bit, as the
  /// field of the tensors a_k I). Throws homesh::Error as above, for a_k not > 0.
  static MetricField isotropic(const CartesianGrid& coarse, std::vector<double> a);
  /// The same metric everywhere.
  static MetricField constant(const Eigen::Matrix2d& M);

  const CartesianGrid& coarse() const { return coarse_; }
  Eigen::Matrix2d metric(int coarse_node) const {
    return a_ ? Eigen::Matrix2d(Eigen::Matrix2d::Identity() * a_[coarse_node]) : M_[coarse_node];
  }
  const Eigen::Matrix2d& inverse(int coarse_node) const { return inverses()[coarse_node]; }

  ShepardStencil stencil(const Eigen::Vector2d& p) const;
  /// Shepard average of the speeds sqrt(N^T M_k^-1 N) at the 4 corners.
  double speed(const Eigen::Vector2d& p, const Eigen::Vector2d& N) const {
    return stencil_speed(stencil(p), N);
  }
  /// The same with the point's stencil given.
  double stencil_speed(const ShepardStencil& s, const Eigen::Vector2d& N) const;
  /// Shepard average of the corner metrics (used where a single tensor is
  /// needed: the seed crystal's shape and the in-circle test of the dual),
  /// or, with a wall layer, its tensor at p itself.
  Eigen::Matrix2d metric_at(const Eigen::Vector2d& p) const;
  /// The same field, its metric_at taken from `layer` (exact where the
  /// coarse nodes cannot resolve a boundary layer; the nodes' tensors, which
  /// the growth's speeds use, stay): the anisotropy and the smallest speed
  /// become at least the layer's at its walls.
  MetricField with_layer(std::shared_ptr<const WallLayer> layer) const;
  const WallLayer* layer() const { return layer_.get(); }
  /// Largest and smallest speed any point can have: max / min over the nodes
  /// of 1/sqrt(lambda_min) and 1/sqrt(lambda_max).
  double max_speed() const { return max_speed_; }
  double min_speed() const { return min_speed_; }
  /// The largest ratio of semi-axes sqrt(lambda_max / lambda_min) over the
  /// nodes, and so anywhere (a Shepard average of isotropic tensors is
  /// isotropic): 1 for an isotropic metric.
  double anisotropy() const { return anisotropy_; }
  /// The same tensor at every coarse node.
  bool uniform() const { return uniform_; }
  /// The same tensors on the same grid.
  bool operator==(const MetricField& o) const;

 private:
  CartesianGrid coarse_;
  // The nodes' tensors, shared by the copies (a field is immutable; the
  // voronoi mesher copies it into each surface's problem and its Lloyd grid),
  // and their inverses, made on first use (only the growth engines' speeds
  // read them, not the exact dual's mesher). On star5_voronoi of the curving
  // corpus (a 352 x 352 grid, 1967 triangles) the stage took 139 ms, 28 of
  // them for the iso field, mostly page faults of fresh memory, and the copies
  // and inverses of its 4 MB of tensors some 20 more. With them shared, the
  // inverses deferred and an isotropic field kept as numbers, the 8 corpus
  // models then over 3x Gmsh frontal's time (best of 3 fresh processes,
  // alternating with the build before): 0.68-0.98 of the time, 1.16 -> 0.89 s
  // in all, the same meshes (scripts/bench/README.md, voronoi_corpus.py).
  struct Tensors {
    std::vector<Eigen::Matrix2d> M;  // or, for an isotropic field,
    std::vector<double> a;           // the numbers a_k of a_k I
    mutable std::vector<Eigen::Matrix2d> Minv;
    mutable std::once_flag inverted;
  };
  MetricField(const CartesianGrid& coarse, std::shared_ptr<Tensors> t);
  bool same_tensors(const MetricField& o) const;
  const std::vector<Eigen::Matrix2d>& inverses() const;
  std::shared_ptr<const Tensors> tensors_;
  const Eigen::Matrix2d* M_ = nullptr;  // tensors_->M.data(), or
  const double* a_ = nullptr;           // tensors_->a.data()
  double max_speed_ = 0.0;
  double min_speed_ = 0.0;
  double anisotropy_ = 1.0;
  bool uniform_ = true;
  std::shared_ptr<const WallLayer> layer_;
};

/// Extreme speeds 1/sqrt(lambda_min), 1/sqrt(lambda_max) of one SPD metric.
double metric_max_speed(const Eigen::Matrix2d& M);
double metric_min_speed(const Eigen::Matrix2d& M);

}  // namespace homesh
