#pragma once
// The isoparametric map of one element at the quadrature points: physical
// points, physical basis gradients and integration weights.
#include <Eigen/Core>

#include "fem/element_tabulation.h"

namespace homesh {

/// For an element with nodes X (2 by n, Gmsh order) and the tabulation `tab`:
///   x      2 by #points physical points, x = X N;
///   dNdx, dNdy  n by #points physical gradients, [dN/dx; dN/dy] = J^-T [dN/du; dN/dv],
///          J = [dx/du dx/dv; dy/du dy/dv] = X [dN/du dN/dv] (Eq 3.3);
///   weight #points, w_q |det J_q|, so that int_e g dx = sum_q weight_q g(x_q).
struct ElementGeometry {
  Eigen::Matrix2Xd x;
  Eigen::MatrixXd dNdx;
  Eigen::MatrixXd dNdy;
  Eigen::VectorXd weight;
};

/// The geometry of the element X at the points of `tab`. Elements of either
/// orientation are accepted; throws homesh::Error if det J vanishes or changes
/// sign between quadrature points (an invalid element).
ElementGeometry element_geometry(const Eigen::Matrix2Xd& X, const ElementTabulation& tab);

/// The same into g, reusing its storage: no allocation once g has the sizes of
/// `tab` (the form the assembly loop uses).
void element_geometry(const Eigen::Matrix2Xd& X, const ElementTabulation& tab, ElementGeometry& g);

}  // namespace homesh
