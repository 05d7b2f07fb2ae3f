#pragma once
// Optimal interior elements (thesis Section 3.8.2, Tables 3.3-3.5, Figs 3.27,
// 3.28): an element with one free node, displaced from the unit equilateral
// element, the rest fixed at its nodes. Every measure's distortion function
// (Eq 3.48, r = 2) is 0 exactly at the equilateral element, so both PRAXIS and
// the brute-force grid must put the free node back where it belongs.
#include <string>

#include "optim/optimal_element.h"
#include "quality/measure_registry.h"

namespace homesh {

/// Fig 3.27(a): the quadratic unit equilateral element with its lower
/// mid-node (node 3) free, moved from (1/2, 0) to (0.7225, -0.2225), i.e.
/// 0.3146 along the direction -45 deg: the displacement along that direction
/// that gives f0 = 1.00 for Q2, the thesis's starting value (Section 3.8.2).
/// The element is valid (certified, det J >= 0.62 of the ideal's).
OptimisationCase quadratic_interior_case();

/// Fig 3.28(a): the cubic unit equilateral element with its interior node
/// (node 9) free, moved from the centroid (1/2, sqrt(3)/6) by 0.1189 along
/// -45 deg, to (0.5841, 0.2046), where f0 = 1.00 for Q2 as in the quadratic
/// case (the thesis gives no f0 here). Valid (det J >= 0.34 of the ideal's).
OptimisationCase cubic_interior_case();

struct InteriorSearch {
  DistortionSettings distortion;  ///< r = 2, element_max, degree-6 Gauss rule
  PraxisOptions praxis;           ///< t0 = 1e-5, h0 = 0.1
  /// Brute force over the box [-1/2, 3/2] x [-1/2, 1/2 + sqrt(3)/2] (the
  /// element's bounding box grown by 1/2), refined around the best point.
  GridSearchOptions grid{101, 3};
};

struct InteriorOptimum {
  std::string measure;
  OptimalElement praxis;
  OptimalElement grid;
  double praxis_error = 0;  ///< distance of PRAXIS's free node from its equilateral position
  double grid_error = 0;    ///< the same for the grid's
};

/// Both searches for measure m on the case (a single free node).
InteriorOptimum find_interior_optimum(const Measure& m, const OptimisationCase& c,
                                      const InteriorSearch& search = {});

}  // namespace homesh
