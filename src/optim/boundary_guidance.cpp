#include "optim/boundary_guidance.h"

#include <cmath>
#include <sstream>

#include "core/error.h"
#include "optim/ideal_element.h"
#include "quality/jacobian_bounds.h"

namespace homesh {
namespace {

// det J of the unit equilateral triangle: the ideal's Jacobian.
const double kIdealJacobian = std::sqrt(3.0) / 2.0;

}  // namespace

OptimisationCase boundary_case(double d) {
  OptimisationCase c;
  c.name = "quadratic_boundary";
  std::ostringstream text;
  text << "quadratic unit equilateral element, lower mid-node fixed at (1/2, " << d
       << "), the other two mid-nodes free";
  c.description = text.str();
  c.order = 2;
  c.start = equilateral_element(2);
  c.start(1, 3) = d;
  c.free_nodes = {4, 5};
  return c;
}

double boundary_asymmetry(const Eigen::Matrix2Xd& X) {
  if (X.cols() != 6) throw Error("boundary asymmetry needs a quadratic triangle (6 nodes)");
  return (Eigen::Vector2d(1.0 - X(0, 5), X(1, 5)) - X.col(4)).norm();
}

std::string to_string(Guidance g) {
  switch (g) {
    case Guidance::valid_symmetric:
      return "valid_symmetric";
    case Guidance::valid_asymmetric:
      return "valid_asymmetric";
    case Guidance::invalid:
      return "invalid";
  }
  return "invalid";
}

BoundaryElement classify_boundary_element(const OptimalElement& optimum,
                                          double symmetry_tolerance) {
  BoundaryElement e;
  e.optimum = optimum;
  e.asymmetry = boundary_asymmetry(optimum.nodes);
  const JacobianBounds bounds = jacobian_bounds(optimum.nodes, 2);
  e.valid = bounds.valid_certified;
  e.min_jacobian = bounds.min_lower / kIdealJacobian;
  if (!e.valid) {
    e.guidance = Guidance::invalid;
  } else if (e.asymmetry > symmetry_tolerance) {
    e.guidance = Guidance::valid_asymmetric;
  } else {
    e.guidance = Guidance::valid_symmetric;
  }
  return e;
}

BoundaryOptimum find_boundary_optimum(const Measure& m, const OptimisationCase& c,
                                      const BoundarySearch& search) {
  if (c.order != 2 || c.free_nodes != std::vector<int>{4, 5}) {
    throw Error("boundary case " + c.name + " must be quadratic with free nodes 4 and 5");
  }
  const FreeNodeDistortion f(m, c.start, c.order, c.free_nodes, search.distortion);
  BoundaryOptimum result;
  result.measure = m.name;
  result.praxis =
      classify_boundary_element(optimise_praxis(f, search.praxis), search.symmetry_tolerance);
  const Eigen::VectorXd lo = Eigen::VectorXd::Constant(4, -0.5);
  const Eigen::VectorXd hi = Eigen::VectorXd::Constant(4, 1.5);
  result.brute_force =
      classify_boundary_element(optimise_grid(f, lo, hi, search.grid), search.symmetry_tolerance);
  return result;
}

}  // namespace homesh
