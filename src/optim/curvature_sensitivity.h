#pragma once
// Sensitivity of the measures to the curvature of a boundary edge (thesis
// Section 3.8.3, Figs 3.30-3.32, Table 3.6): the quadratic unit equilateral
// element with its lower mid-node moved to (1/2, d), chi = d / c with c = 1 the
// edge's chord; d < 0 bends the edge outwards (convex), d > 0 into the element
// (concave, towards a vanishing Jacobian). The other nodes stay at their
// straight positions: Fig 3.32 plots f against the boundary node alone, and
// f = 0 at chi = 0 is the equilateral element (with the other mid-nodes
// optimised, Q1, Q4 and Q17 would reach f = 0 at every chi, as in Fig 3.29(b),
// and could not rank among the most sensitive as Table 3.6 has them).
#include <string>
#include <utility>
#include <vector>

#include "optim/free_node_distortion.h"
#include "optim/thesis_tables.h"
#include "quality/measure_registry.h"

namespace homesh {

/// The quadratic element of Fig 3.30 with curvature chi (2 by 6, Gmsh order).
Eigen::Matrix2Xd curved_edge_element(double chi);

/// f (Eq 3.48) of measure m on curved_edge_element(chi).
double curvature_distortion(const Measure& m, double chi, const DistortionSettings& s = {});

/// f of every measure (registry order) at chi.
std::vector<std::pair<std::string, double>> curvature_distortions(double chi,
                                                                  const DistortionSettings& s = {});

/// Measures ranked by f descending, those within `relative_tie` of each other
/// grouped as equal (Q6 = Q7 = Q11 = Q12 are equal in 2D) and listed in input order.
Ordering rank_by_value(const std::vector<std::pair<std::string, double>>& values,
                       double relative_tie = 1e-6);

/// How far two orderings of the same measures agree: Spearman's rho of the
/// positions (tied groups take their mean rank); measures missing from either
/// are skipped.
double ordering_correlation(const Ordering& a, const Ordering& b);

/// "Qa > Qb = Qc > ...".
std::string to_string(const Ordering& ordering);

}  // namespace homesh
