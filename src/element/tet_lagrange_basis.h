#pragma once
// Lagrange basis of order p on the reference tetrahedron (0,0,0), (1,0,0), (0,1,0),
// (0,0,1), interpolating at tetrahedron_nodes(p) (Gmsh ordering), with first
// derivatives: the triangle's construction (element/lagrange_basis.h; Silvester
// 1969) with four barycentric coordinates (l0, l1, l2, l3) = (1 - u - v - w, u, v, w)
// and node k at the barycentric multi-index (p - i - j - l, i, j, l),
//
//   N_k = R_c(l0) R_a(l1) R_b(l2) R_d(l3),   R_m(l) = prod_{s=0}^{m-1} (p l - s) / (s + 1),
//
// 1 at node k, 0 at the others, no linear system solved.
#include <Eigen/Core>

namespace homesh {

class TetLagrangeBasis {
 public:
  /// Order 1 <= p <= kMaxOrder (core/mesh.h); throws homesh::Error otherwise.
  explicit TetLagrangeBasis(int p);

  int order() const { return p_; }
  int size() const { return static_cast<int>(nodes_.cols()); }
  /// 3 by size() reference nodes.
  const Eigen::Matrix3Xd& nodes() const { return nodes_; }

  /// size() values N_k(u, v, w).
  Eigen::VectorXd values(const Eigen::Vector3d& uvw) const;
  /// 3 by size() derivatives: row r dN_k / d(u, v, w)_r.
  Eigen::Matrix3Xd gradients(const Eigen::Vector3d& uvw) const;
  /// Writes the size() values and/or derivatives at uvw (null outputs skipped;
  /// dN holds 3 size() entries, node k's gradient at 3 k .. 3 k + 2).
  void evaluate(const Eigen::Vector3d& uvw, double* N, double* dN) const;

 private:
  int p_;
  Eigen::Matrix3Xd nodes_;
  Eigen::Matrix4Xi multi_index_;  // barycentric (c, a, b, d) of each node
};

}  // namespace homesh
