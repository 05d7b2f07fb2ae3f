#include "fem/element_tabulation.h"

#include <string>
#include <utility>

#include "core/error.h"
#include "element/lagrange_basis.h"
#include "element/quad_lagrange_basis.h"
#include "element/quad_reference_nodes.h"
#include "element/reference_nodes.h"
#include "element/square_quadrature.h"

namespace homesh {

int stiffness_quadrature_degree(int order, int margin) {
  if (margin < 0)
    throw Error("stiffness_quadrature_degree: margin " + std::to_string(margin) + " < 0");
  return 2 * (order - 1) + margin;
}

ElementTabulation tabulate_element(int order, int quadrature_degree) {
  const LagrangeBasis basis(order);
  ElementTabulation tab;
  tab.order = order;
  tab.rule = triangle_quadrature(quadrature_degree);
  tab.N = basis.tabulate_values(tab.rule.points);
  basis.tabulate_gradients(tab.rule.points, tab.dNdu, tab.dNdv);
  return tab;
}

int quad_stiffness_quadrature_degree(int order, int margin) {
  if (margin < 0)
    throw Error("quad_stiffness_quadrature_degree: margin " + std::to_string(margin) + " < 0");
  return 2 * order + margin;
}

ElementTabulation tabulate_quad_element(int order, int quadrature_degree) {
  const QuadLagrangeBasis basis(order);
  ElementTabulation tab;
  tab.order = order;
  tab.quad = true;
  tab.rule = square_quadrature(quadrature_degree);
  tab.N = basis.tabulate_values(tab.rule.points);
  basis.tabulate_gradients(tab.rule.points, tab.dNdu, tab.dNdv);
  return tab;
}

namespace {

// tab with the nodes of `lattice` appended to its rule: the rule's weights scaled by
// 1 - lattice_weight, the lattice sharing lattice_weight of the area equally.
template <class Basis>
ElementTabulation with_lattice(ElementTabulation tab, const Basis& basis,
                               const Eigen::Matrix2Xd& lattice, double lattice_weight) {
  const int q = static_cast<int>(tab.rule.weights.size()), l = static_cast<int>(lattice.cols());
  const double area = tab.rule.weights.sum();
  QuadratureRule rule;
  rule.points.resize(2, q + l);
  rule.points << tab.rule.points, lattice;
  rule.weights.resize(q + l);
  rule.weights << (1 - lattice_weight) * tab.rule.weights,
      Eigen::VectorXd::Constant(l, lattice_weight * area / l);
  tab.rule = rule;
  tab.N = basis.tabulate_values(rule.points);
  basis.tabulate_gradients(rule.points, tab.dNdu, tab.dNdv);
  return tab;
}

}  // namespace

ElementTabulation tabulate_element_and_lattice(int order, int degree, double lattice_weight) {
  ElementTabulation tab = tabulate_element(order, degree);
  if (!(lattice_weight > 0)) return tab;
  return with_lattice(std::move(tab), LagrangeBasis(order), reference_nodes(2 * (order - 1)),
                      lattice_weight);
}

ElementTabulation tabulate_quad_element_and_lattice(int order, int degree, double lattice_weight) {
  ElementTabulation tab = tabulate_quad_element(order, degree);
  if (!(lattice_weight > 0)) return tab;
  return with_lattice(std::move(tab), QuadLagrangeBasis(order), quad_reference_nodes(2 * order - 1),
                      lattice_weight);
}

}  // namespace homesh
