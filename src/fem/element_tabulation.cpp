#include "fem/element_tabulation.h"

#include <string>

#include "core/error.h"
#include "element/lagrange_basis.h"

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

}  // namespace homesh
