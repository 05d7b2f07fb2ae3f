#include "optim/interior_optimum.h"

#include <cmath>

#include "core/error.h"
#include "optim/ideal_element.h"

namespace homesh {

OptimisationCase quadratic_interior_case() {
  OptimisationCase c;
  c.name = "quadratic_interior";
  c.description =
      "quadratic unit equilateral element, lower mid-node free, started at (0.7225, -0.2225)";
  c.order = 2;
  c.start = equilateral_element(2);
  c.start.col(3) << 0.7225, -0.2225;
  c.free_nodes = {3};
  return c;
}

OptimisationCase cubic_interior_case() {
  OptimisationCase c;
  c.name = "cubic_interior";
  c.description = "cubic unit equilateral element, interior node free, started at (0.5841, 0.2046)";
  c.order = 3;
  c.start = equilateral_element(3);
  c.start.col(9) << 0.5841, 0.2046;
  c.free_nodes = {9};
  return c;
}

InteriorOptimum find_interior_optimum(const Measure& m, const OptimisationCase& c,
                                      const InteriorSearch& search) {
  if (c.free_nodes.size() != 1) throw Error("interior case " + c.name + " needs one free node");
  const int node = c.free_nodes.front();
  const Eigen::Vector2d ideal = equilateral_element(c.order).col(node);
  const FreeNodeDistortion f(m, c.start, c.order, c.free_nodes, search.distortion);
  InteriorOptimum result;
  result.measure = m.name;
  result.praxis = optimise_praxis(f, search.praxis);
  const Eigen::Vector2d lo(-0.5, -0.5), hi(1.5, 0.5 + std::sqrt(3.0) / 2.0);
  result.grid = optimise_grid(f, lo, hi, search.grid);
  result.praxis_error = (result.praxis.nodes.col(node) - ideal).norm();
  result.grid_error = (result.grid.nodes.col(node) - ideal).norm();
  return result;
}

}  // namespace homesh
