#pragma once
// A quality measure (quality/measure_registry.h) evaluated over one element:
// at each sample point k, W_k = J_k inv(J_ri) (quality/ideal_jacobian.h) with
// J_k from the element's nodes (Eq 3.3), then the measure's quality.
//
// Two references for the size-sensitive measures:
//  - Reference::ideal (default): every measure's own pointwise quality,
//    normalised against the unit equilateral element (ratio_quality.h).
//  - Reference::element_max: the thesis's normalisation (text after Eq 3.49)
//    Q = raw / max raw over the element's points, for the measures with
//    thesis_max_normalised (Q2, Q3, Q4, Q5, Q17); 0 where omega <= 0. It is
//    blind to any distortion with constant W (thesis Table 3.2, column T2),
//    and makes these measures scale-invariant over an element. Other measures
//    are evaluated as with Reference::ideal.
// Measures of the whole element (Q1) take the same value at every point.
#include <Eigen/Core>

#include "quality/element_sampling.h"
#include "quality/measure_registry.h"

namespace homesh {

enum class Reference { ideal, element_max };

/// What a measure needs of the whole element besides W at one point.
struct ElementScale {
  double element_value = 0.0;  ///< the element's quality, for !m.pointwise()
  double max_raw = 0.0;        ///< largest raw value where omega > 0 (element_max)
};

/// The ElementScale of measure m over the element with nodes X
/// (2 by s.node_count(), Gmsh order) sampled at the points of s.
ElementScale element_scale(const Measure& m, const ElementSampling& s, const Eigen::Matrix2Xd& X,
                           Reference ref);

/// Quality in [0, 1] of measure m at a point with ideal Jacobian W, given the
/// element's scale. No allocation.
double point_quality(const Measure& m, const Eigen::Matrix2d& W, const ElementScale& scale,
                     Reference ref);

/// Qualities at the sample points and their minimum.
struct ElementQuality {
  Eigen::VectorXd values;  ///< one per point of the sampling
  double min = 0.0;
};

/// Measure m over the element with nodes X (2 by s.node_count(), Gmsh order)
/// at the points of s.
ElementQuality element_quality(const Measure& m, const ElementSampling& s,
                               const Eigen::Matrix2Xd& X, Reference ref = Reference::ideal);

/// Measure m over the order-p element with nodes X (2 by (p+1)(p+2)/2, Gmsh
/// order) at the reference points uv (2 by #points).
ElementQuality element_quality(const Measure& m, const Eigen::Matrix2Xd& X, int p,
                               const Eigen::Matrix2Xd& uv, Reference ref = Reference::ideal);

}  // namespace homesh
