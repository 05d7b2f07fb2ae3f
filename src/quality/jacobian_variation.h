#pragma once
// Q1, the variation of the Jacobian over an element (Dey et al.; thesis
// Eq 3.33):
//
//   Q1 = min J / max J,
//
// J = det of the reference -> physical Jacobian (Eq 3.3) at the sample points
// of the element. The ratio is the same for omega = det W (W = J inv(J_ri)
// differs by a constant factor), so it is scale-, rotation- and
// label-invariant. It is one number per element (constant over it, Fig 3.13),
// 1 for any element with constant Jacobian (straight-sided), 0 if J <= 0
// anywhere. The thesis's generalisation min Qn / max Qn is not separate here.
#include <Eigen/Core>

#include "quality/element_sampling.h"

namespace homesh {

/// Q1 over the element with nodes X (2 by s.node_count(), Gmsh order) sampled
/// at the points of s: min J / max J, 0 if min J <= 0.
double jacobian_variation(const ElementSampling& s, const Eigen::Matrix2Xd& X);

}  // namespace homesh
