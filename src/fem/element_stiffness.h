#pragma once
// The elemental stiffness matrix of plane linear elasticity, thesis Eqs 4.14-4.15.
#include <Eigen/Core>

#include "fem/element_geometry.h"

namespace homesh {

/// Ke (2n by 2n, n = #nodes of the element), dofs ordered as in Eq 4.14:
/// [u_1 .. u_n, v_1 .. v_n], so Ke = [A B; B^T C] with (Eq 4.15)
///   A_ij = int (lambda + 2 mu) dNi/dx dNj/dx + mu dNi/dy dNj/dy,
///   B_ij = int lambda dNi/dx dNj/dy + mu dNi/dy dNj/dx,
///   C_ij = int mu dNi/dx dNj/dx + (lambda + 2 mu) dNi/dy dNj/dy,
/// integrated by the rule of `g`; lambda and mu hold Lame's constants at its
/// points (#points each). Symmetric, positive semi-definite with the three rigid
/// motions in its kernel when lambda + mu > 0 and mu > 0.
Eigen::MatrixXd element_stiffness(const ElementGeometry& g, const Eigen::VectorXd& lambda,
                                  const Eigen::VectorXd& mu);

/// The lower triangle of the same Ke into K (2n by 2n, resized; the strict
/// upper triangle is left unspecified), with `scratch` (n by 2 #points) as
/// workspace: no allocation once both have their sizes.
void element_stiffness_lower(const ElementGeometry& g, const Eigen::VectorXd& lambda,
                             const Eigen::VectorXd& mu, Eigen::MatrixXd& K,
                             Eigen::MatrixXd& scratch);

/// The same from the element's nodes X (2 by n, Gmsh order, order tab.order).
Eigen::MatrixXd element_stiffness(const Eigen::Matrix2Xd& X, const ElementTabulation& tab,
                                  const Eigen::VectorXd& lambda, const Eigen::VectorXd& mu);

}  // namespace homesh
