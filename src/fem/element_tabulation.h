#pragma once
// The Lagrange basis of order p tabulated at the points of a triangle rule (or
// of a square rule, for quadrilaterals), shared by every element of one kind
// of a mesh (elements differ only by their nodes).
#include <Eigen/Core>

#include "element/quadrature.h"

namespace homesh {

/// Basis of order `order` at the `rule` points: N, dN/du, dN/dv, each
/// (p+1)(p+2)/2 by #points, nodes in Gmsh order (element/reference_nodes.h);
/// for a quadrilateral (quad = true) the (p+1)^2 functions of
/// element/quad_lagrange_basis.h at points of the square [0, 1]^2.
struct ElementTabulation {
  int order = 1;
  bool quad = false;
  QuadratureRule rule;
  Eigen::MatrixXd N;
  Eigen::MatrixXd dNdu;
  Eigen::MatrixXd dNdv;
};

/// Quadrature degree for the stiffness of order-p elements: 2 (p - 1), exact for
/// straight-sided elements with constant (lambda, mu) (the integrand of Eq 4.15
/// is then a product of two gradients of degree p - 1), plus `margin` >= 0 for
/// curved elements (rational integrand) and varying coefficients.
int stiffness_quadrature_degree(int order, int margin);

/// The tabulation of order 1 <= order <= kMaxOrder at triangle_quadrature(degree).
ElementTabulation tabulate_element(int order, int quadrature_degree);

/// Quadrature degree per variable for the stiffness of order-p quadrilaterals:
/// 2 p, exact for parallelograms (affine quadrilaterals, J constant) with
/// constant (lambda, mu): dN/du is of degree p - 1 in u and p in v (the
/// complete basis has degree p per variable), so a physical gradient J^-T
/// [dN/du; dN/dv] is of degree p per variable and a product of two of degree
/// 2 p; plus `margin` >= 0 as stiffness_quadrature_degree. The same degree
/// also integrates dN/dx det J (degree 2 p - 1 per variable on any quadrilateral),
/// which is what the patch test needs on curved ones. (p + 1 + margin / 2)^2 points.
int quad_stiffness_quadrature_degree(int order, int margin);

/// The quadrilateral tabulation (quad = true) of order 1 <= order <= kMaxOrder
/// at square_quadrature(degree) (element/square_quadrature.h).
ElementTabulation tabulate_quad_element(int order, int quadrature_degree);

/// The tabulation at triangle_quadrature(degree) and, with lattice_weight > 0, also at
/// the nodes of the order 2 (order - 1) lattice (where det J's Bezier coefficients live,
/// corners and edges included), the rule's weights scaled by 1 - lattice_weight and the
/// lattice sharing lattice_weight of the area equally (an objective's sample points,
/// not an exact rule: the high-order optimiser's energy, curving/optimise_mesh.h).
ElementTabulation tabulate_element_and_lattice(int order, int degree, double lattice_weight);

/// The quadrilateral analogue (quad = true): square_quadrature(degree) and, with
/// lattice_weight > 0, the nodes of the square's order 2 order - 1 lattice
/// (quad_reference_nodes: det J is of degree 2p - 1 per variable and its (2p)^2
/// tensor-product Bezier coefficients, quality/quad_bezier_jacobian.h, sit there;
/// corners and edges included), the weights shared as tabulate_element_and_lattice.
ElementTabulation tabulate_quad_element_and_lattice(int order, int degree, double lattice_weight);

}  // namespace homesh
