#pragma once
// The one table of the high-order quality measures of thesis Table 3.1
// (Eqs 3.33-3.47), keyed by name "Q1" .. "Q17". It drives the CLI choices, the
// .msh view names, the Python API and the test loops: add a measure here and
// everything else sees it.
//
// Conventions: W (2 by 2) is the Jacobian of the map from the ideal (unit
// equilateral) element to the physical one, W = J inv(J_ri)
// (quality/ideal_jacobian.h); omega = det W; D = W^T W (Eq 3.14). Every
// quality is normalised to [0, 1], 1 = ideal (Section 3.7), and is 0 where
// omega <= 0 (invalid). The normalisation is pointwise, against the ideal
// element: see `normalisation` of each entry and quality/ratio_quality.h.
//
// Q15 (Salem et al., quadratic triangles only) is not in the table: Eq 3.46,
// Q15 = gamma_max (J_ref gamma_min^2)^-1, names two parameters gamma_min and
// gamma_max "associated with the geometric proofs" of Salem et al.'s mid-node
// admissible spaces without defining them, and the thesis itself leaves Q15
// out of every assessment (Tables 3.2-3.7) as inapplicable to its gallery.
// measure("Q15") throws homesh::Error saying so.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "quality/element_sampling.h"

namespace homesh {

/// A measure of W at one point.
using PointMeasure = double (*)(const Eigen::Matrix2d& W);
/// A measure of W (3 by 3) at one point of a tetrahedron (issue 24).
using PointMeasure3 = double (*)(const Eigen::Matrix3d& W);
/// A measure of a whole element with nodes X (2 by s.node_count(), Gmsh order)
/// sampled at the points of s.
using ElementMeasure = double (*)(const ElementSampling& s, const Eigen::Matrix2Xd& X);

/// Invariances claimed by thesis Table 3.7 (true = invariant).
struct Invariance {
  bool label;
  bool scale;
  bool rotation;
};

struct Measure {
  std::string name;     ///< "Q1" .. "Q17"
  std::string title;    ///< Table 3.1 name, e.g. "Laplace"
  std::string formula;  ///< the Table 3.1 formula in 2D, as text
  /// How the raw value is mapped to [0, 1]: "min(x, 1/x), x = ..." folds the
  /// ratio to the ideal value (ratio_quality.h); "2 raw" or "none: ..." scale a
  /// raw value that is largest at the ideal.
  std::string normalisation;
  std::string source;     ///< thesis equation and the paper it cites
  Invariance invariance;  ///< claimed by Table 3.7
  /// The thesis normalises this measure by its largest value over the element,
  /// Q / Qmax (text after Eq 3.49): Q2, Q3, Q4, Q5, Q17.
  bool thesis_max_normalised;
  /// The Table 3.1 formula at one point, meaningful for omega > 0 (for Q1 the
  /// sampled quantity omega).
  PointMeasure raw;
  /// Normalised quality at one point; null for measures of the whole element.
  PointMeasure quality;
  /// Normalised quality of the whole element (Q1); null for pointwise measures.
  ElementMeasure element;

  /// On tetrahedra (quality/volume_measures.h): the raw value and the
  /// normalised quality with d = 3; null for Q1, a measure of the whole element
  /// in any dimension (quality/volume_quality.h computes it).
  PointMeasure3 raw3 = nullptr;
  PointMeasure3 quality3 = nullptr;

  /// True if the quality is a function of W at one point.
  bool pointwise() const { return quality != nullptr; }
};

/// All measures, in thesis order Q1 .. Q17 (without Q15).
const std::vector<Measure>& measures();

/// Names of the fields (Gmsh views, meshio cell data) of measure q: its
/// minimum over each element, "homesh: Q4 Equal volume, element minimum", and
/// its values at each element's nodes, "homesh: Q4 Equal volume, at nodes".
/// The formula and thesis equation are in `homesh --measures`.
std::string element_field_name(const Measure& q);
std::string node_field_name(const Measure& q);

/// The measure called `name` ("Q7"; case-insensitive). Throws homesh::Error
/// naming it and listing the valid names if there is none.
const Measure& measure(const std::string& name);

}  // namespace homesh
