#pragma once
// Lagrange basis of order p on the reference square [0, 1]^2, interpolating at
// quad_reference_nodes(p) (Gmsh ordering), with first derivatives.
//
// Tensor product: node k at (i, j) / p (quad_reference_node_indices) has
//
//   N_k(u, v) = L_i(u) L_j(v),   L_i(t) = prod_{s != i} (p t - s) / (i - s),
//
// the 1D Lagrange polynomials of degree p at t = 0, 1/p, ..., 1. Each N_k is
// of degree p in u and in v (the complete, not serendipity, element: Gmsh's
// "Quadrilateral (p+1)^2"). Evaluation costs O(p^2) for the two factor tables
// plus 2 (values) or 4 (derivatives) products per basis function.
#include <Eigen/Core>

#include "core/mesh.h"

namespace homesh {

class QuadLagrangeBasis {
 public:
  /// Order 1 <= p <= kMaxOrder (core/mesh.h); throws homesh::Error otherwise.
  explicit QuadLagrangeBasis(int p);

  int order() const { return p_; }
  int size() const { return static_cast<int>(nodes_.cols()); }
  /// 2 by size() reference nodes.
  const Eigen::Matrix2Xd& nodes() const { return nodes_; }

  /// size() values N_k(u, v).
  Eigen::VectorXd values(const Eigen::Vector2d& uv) const;
  /// 2 by size() derivatives: row 0 dN_k/du, row 1 dN_k/dv.
  Eigen::Matrix2Xd gradients(const Eigen::Vector2d& uv) const;

  /// size() by #points dN/du and dN/dv at the columns of `uv` (resized here).
  void tabulate_gradients(const Eigen::Matrix2Xd& uv, Eigen::MatrixXd& dNdu,
                          Eigen::MatrixXd& dNdv) const;

 private:
  // Writes the size() values and/or derivatives at uv; null outputs are skipped.
  void evaluate(const Eigen::Vector2d& uv, double* N, double* dNdu, double* dNdv) const;

  int p_;
  Eigen::Matrix2Xd nodes_;
  Eigen::Matrix2Xi index_;  // (i, j) of each node
};

}  // namespace homesh
