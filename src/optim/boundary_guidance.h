#pragma once
// Element quality in the presence of boundaries (thesis Section 3.8.3,
// Fig 3.29): the quadratic unit equilateral element with its lower edge
// curved symmetrically and fixed (the boundary), its two other mid-nodes free.
// A measure "guides" the optimisation correctly if the optimal element is
// valid and, as the setup is mirror-symmetric, symmetric; the thesis found
// valid symmetric, valid asymmetric and invalid optima (the boundary_guidance
// column of tests/data/thesis/table_3_7_invariance.csv).
#include <string>

#include "optim/optimal_element.h"
#include "quality/measure_registry.h"

namespace homesh {

/// Height of the lower mid-node, d = 0.3518 (a concave edge, sagitta 0.35 of
/// the edge length): with the other mid-nodes straight it gives f0 = 5.45 for
/// Q4 and 2.56 for Q3 (r = 2), the thesis's starting values of Fig 3.29(d), (e)
/// (5.45 and 2.55), so it is the thesis's curvature.
constexpr double kFig329Height = 0.3518;

/// Fig 3.29(a): the quadratic unit equilateral element with node 3 at
/// (1/2, d), fixed; nodes 4 and 5 (mid-nodes of edges 1-2 and 2-0) free,
/// starting at their edges' midpoints.
OptimisationCase boundary_case(double d = kFig329Height);

/// Distance between node 4 and the mirror image of node 5 in the line x = 1/2,
/// the axis of symmetry of the case (0 for a symmetric element).
double boundary_asymmetry(const Eigen::Matrix2Xd& quadratic);

enum class Guidance { valid_symmetric, valid_asymmetric, invalid };

/// "valid_symmetric", "valid_asymmetric", "invalid" (the thesis table's words).
std::string to_string(Guidance g);

/// How an optimal element of the boundary case turned out.
struct BoundaryElement {
  OptimalElement optimum;
  double asymmetry = 0;  ///< boundary_asymmetry of optimum.nodes
  /// det J > 0 over the whole element (certified Bezier bounds,
  /// quality/jacobian_bounds.h), not only at the Gauss points f sees.
  bool valid = false;
  /// Certified lower bound of det J / det J of the ideal element.
  double min_jacobian = 0;
  Guidance guidance = Guidance::invalid;
};

/// Classifies the optimal element of the boundary case (quadratic) found by a
/// search: invalid unless det J > 0 everywhere, else asymmetric if its
/// boundary_asymmetry exceeds symmetry_tolerance, else symmetric.
BoundaryElement classify_boundary_element(const OptimalElement& optimum, double symmetry_tolerance);

struct BoundarySearch {
  DistortionSettings distortion;  ///< r = 2, element_max, degree-6 Gauss rule
  PraxisOptions praxis;           ///< t0 = 1e-5, h0 = 0.1
  /// Asymmetry above this (1 % of the edge length) is an asymmetric element;
  /// PRAXIS's tolerance leaves about 1e-3 in flat valleys.
  double symmetry_tolerance = 1e-2;
  /// Brute force over both free nodes in [-1/2, 3/2]^2 each (4 dimensions):
  /// 21^4 points, then two zoom-ins, to a spacing of 0.004.
  GridSearchOptions grid{21, 2};
};

struct BoundaryOptimum {
  std::string measure;
  /// PRAXIS from the straight mid-nodes, the thesis's procedure.
  BoundaryElement praxis;
  /// The global minimum by brute force: if it is lower than PRAXIS's, PRAXIS
  /// stopped short (the thesis's "fail-safe alternative", Section 3.8.2).
  BoundaryElement brute_force;
};

/// Both searches for measure m on the boundary case c.
BoundaryOptimum find_boundary_optimum(const Measure& m, const OptimisationCase& c,
                                      const BoundarySearch& search = {});

}  // namespace homesh
