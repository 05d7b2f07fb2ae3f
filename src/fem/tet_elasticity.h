#pragma once
// Linear elasticity on Lagrange tetrahedra of order p (issue 24): the 3D form of
// the elemental stiffness of thesis Eqs 4.14-4.15, for the elastic analogy in 3D.
#include <Eigen/Core>
#include <vector>

#include "element/quadrature.h"

namespace homesh {

/// The reference tetrahedron's data for elements of order p: a quadrature rule
/// and the basis gradients at its points.
struct TetTabulation {
  int order = 1;
  TetQuadratureRule rule;
  /// One per quadrature point: 3 by (p+1)(p+2)(p+3)/6, column k dN_k / d(u, v, w).
  std::vector<Eigen::Matrix3Xd> gradients;
  /// The reference nodes (element/tet_reference_nodes.h).
  Eigen::Matrix3Xd reference_nodes;
  /// products[3 r + s](a, b) = int dN_a/du_r dN_b/du_s over the reference element.
  Eigen::MatrixXd products[9];
};

/// The tabulation of order p with tetrahedron_quadrature(degree). Degree 2(p-1)
/// integrates the stiffness of a straight-sided element exactly.
TetTabulation tetrahedron_tabulation(int p, int degree);

/// Ke (3n by 3n, n nodes; dofs node-major: node k's x, y, z at 3k, 3k+1, 3k+2)
/// of linear elasticity with Lame constants lambda and mu on the tetrahedron
/// with nodes X (3 by n, Gmsh order, the isoparametric map of t's order):
///   Ke_(a i),(b j) = int lambda dNa/dx_i dNb/dx_j
///                      + mu (delta_ij grad Na . grad Nb + dNa/dx_j dNb/dx_i) dx,
/// the 3D form of thesis Eq 4.15 (there in blocks [A B; B^T C] over u then v).
/// Symmetric, positive semi-definite with the six rigid motions in its kernel.
/// A straight-sided element (nodes at the affine map of its corners) gets the
/// exact integral from t's products (constant J); a curved one t's quadrature.
/// `volume`, if given, receives the element's volume (int det J du dv dw).
Eigen::MatrixXd tetrahedron_stiffness(const Eigen::Matrix3Xd& X, const TetTabulation& t,
                                      double lambda, double mu, double* volume = nullptr);

}  // namespace homesh
