#pragma once
// Distortion of a quality measure and its average over an element, the
// objective the thesis minimises to find optimal elements (Section 3.8.1).
#include <Eigen/Core>

#include "quality/element_quality.h"
#include "quality/element_sampling.h"
#include "quality/measure_registry.h"

namespace homesh {

/// Eq 3.49: Theta = 1/Q - 1 for a normalised quality Q in (0, 1]: 0 at the
/// ideal, growing without bound as Q -> 0; +infinity for Q <= 0 (invalid).
double distortion(double q);

/// Eq 3.48, the element distortion function
///
///   f = ( (1 / |A_e|) sum_i w_i Theta_i^r |J_i| )^(1/r),   r > 1,
///
/// over the points i of the quadrature sampling `rule` (built from a
/// QuadratureRule, so it has weights w_i), with Theta_i the distortion of
/// measure m at point i (Reference as in element_quality.h), |J_i| the modulus
/// of det J there and |A_e| = sum_i w_i |J_i| (the element's area by the same
/// rule, so that a constant Theta gives f = Theta for every r). f is the r-mean
/// of Theta over the element, non-decreasing in r, 0 only for an element
/// distortion-free at every point, +infinity if the measure is 0 at any point.
/// The thesis used r = 2 and a 12-point Gauss rule. Throws homesh::Error if
/// `rule` has no weights, X has the wrong number of nodes, or r <= 1.
double distortion_function(const Measure& m, const ElementSampling& rule, const Eigen::Matrix2Xd& X,
                           double r, Reference ref = Reference::ideal);

}  // namespace homesh
