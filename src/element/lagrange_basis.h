#pragma once
// Lagrange basis of order p on the reference triangle (0,0), (1,0), (0,1),
// interpolating at reference_nodes(p) (Gmsh ordering), with first derivatives.
#include <Eigen/Core>
#include <Eigen/LU>

namespace homesh {

class LagrangeBasis {
 public:
  /// Order p >= 1.
  explicit LagrangeBasis(int p);

  int order() const { return p_; }
  int size() const { return static_cast<int>(nodes_.cols()); }
  /// 2 by size() reference nodes.
  const Eigen::Matrix2Xd& nodes() const { return nodes_; }

  /// size() values N_i(u, v).
  Eigen::VectorXd values(const Eigen::Vector2d& uv) const;
  /// 2 by size() derivatives: row 0 dN_i/du, row 1 dN_i/dv.
  Eigen::Matrix2Xd gradients(const Eigen::Vector2d& uv) const;

  /// size() by #points values at the columns of the 2 by #points matrix `uv`.
  Eigen::MatrixXd tabulate_values(const Eigen::Matrix2Xd& uv) const;
  /// size() by #points dN/du and dN/dv at the columns of `uv`.
  void tabulate_gradients(const Eigen::Matrix2Xd& uv, Eigen::MatrixXd& dNdu,
                          Eigen::MatrixXd& dNdv) const;

 private:
  int p_;
  Eigen::Matrix2Xd nodes_;
  Eigen::MatrixXd coeffs_;  // monomial (or orthogonal) coefficients of each N_i
};

}  // namespace homesh
