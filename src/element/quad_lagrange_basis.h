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
#include "element/nodal_basis.h"

namespace homesh {

class QuadLagrangeBasis : public NodalBasis<QuadLagrangeBasis> {
 public:
  /// Order 1 <= p <= kMaxOrder (core/mesh.h); throws homesh::Error otherwise.
  explicit QuadLagrangeBasis(int p);

 private:
  friend class NodalBasis<QuadLagrangeBasis>;
  // Writes the size() values and/or derivatives at uv; null outputs are skipped.
  void evaluate(const Eigen::Vector2d& uv, double* N, double* dNdu, double* dNdv) const;

  Eigen::Matrix2Xi index_;  // (i, j) of each node
};

}  // namespace homesh
