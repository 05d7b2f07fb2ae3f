#pragma once
// Lagrange basis of order p on the reference triangle (0,0), (1,0), (0,1),
// interpolating at reference_nodes(p) (Gmsh ordering), with first derivatives.
//
// Construction (Silvester 1969, "High-order polynomial triangular finite
// elements for potential problems"): with barycentric coordinates
// (l0, l1, l2) = (1 - u - v, u, v) and node k at barycentric multi-index
// (c, a, b) = (p - i - j, i, j) (see reference_node_indices),
//
//   N_k(u, v) = R_c(l0) R_a(l1) R_b(l2),   R_m(l) = prod_{s=0}^{m-1} (p l - s) / (s + 1).
//
// R_m vanishes at l = 0, 1/p, ..., (m-1)/p and is 1 at l = m/p, so N_k is 1 at
// node k and 0 at the others. No linear system is solved: evaluation costs
// O(p) per point for the 3 factor tables plus 2 (values) or 6 (derivatives)
// products per basis function, and is accurate to rounding for every order
// allowed.
#include <Eigen/Core>

#include "core/mesh.h"
#include "element/nodal_basis.h"

namespace homesh {

class LagrangeBasis : public NodalBasis<LagrangeBasis> {
 public:
  /// Order 1 <= p <= kMaxOrder (core/mesh.h); throws homesh::Error otherwise.
  explicit LagrangeBasis(int p);

 private:
  friend class NodalBasis<LagrangeBasis>;
  // Writes the size() values and/or derivatives at uv; null outputs are skipped.
  void evaluate(const Eigen::Vector2d& uv, double* N, double* dNdu, double* dNdv) const;

  Eigen::Matrix3Xi multi_index_;  // barycentric (c, a, b) of each node
};

}  // namespace homesh
