#pragma once
// Thesis Table 3.2, made quantitative: does measure Qk represent the
// distortion of gallery element Tn (Section 3.7.3)?
//
// The thesis judged its colour plots of ~200 samples per element (Figs
// 3.13-3.26) by eye and names three ways to fail: not seeing a distortion
// (Q13 on T2, T5, T6), seeing it only "as a whole" without "a varying
// distribution over each element" (Q1, which fails every distorted element),
// and giving "inappropriate results" (Q2, Q3, Q5 on T4-T6). Our criterion
// turns each into a number. With Theta = 1/Q - 1 (Eq 3.49) the measure's
// distortion, Q normalised as in the thesis (Q / Qmax over the element for
// Q1-Q5, Q17: Reference::element_max), and the samples the order-18 lattice
// (190 points):
//
//  1. detects: f > detection, f the element distortion function (Eq 3.48,
//     r = 2) over a Gauss rule;
//  2. distributes: where W varies over the element (a curved or non-affine
//     element), Theta varies over the samples too;
//  3. not inverted: Spearman's rho of Theta and the Hencky strain
//       H(x) = sqrt(log^2 sigma_1 + log^2 sigma_2),  sigma_i singular values of W,
//     over the samples is above -inversion. H is a measure-free pointwise
//     distortion: the logarithmic distance of W from the rotations, 0 exactly
//     where the element is locally the unit equilateral one. A strong negative
//     rho means the measure rates the most strained points as the best.
//
// Qk represents an ideal Tn (H = 0 everywhere: T1) if it detects nothing, and
// a distorted Tn if it passes 1-3 (2 and 3 are void on a constant W, e.g. T2).
#include <string>
#include <vector>

#include "optim/free_node_distortion.h"
#include "optim/gallery.h"
#include "optim/thesis_tables.h"
#include "quality/measure_registry.h"

namespace homesh {

struct RepresentationCriterion {
  double detection = 1e-3;        ///< f above this is a detected distortion
  double inversion = 0.5;         ///< rho <= -inversion is an inverted distribution
  int lattice_order = 18;         ///< sample points: reference_nodes(lattice_order)
  DistortionSettings distortion;  ///< f: r = 2, element_max, degree-6 Gauss rule
};

/// H(x) above for W = J inv(J_ri) (2 by 2); +infinity if det W <= 0.
double hencky_distortion(const Eigen::Matrix2d& W);

struct RepresentationCell {
  std::string measure;  ///< "Q1" ..
  std::string element;  ///< "T1" ..
  double f = 0;         ///< Eq 3.48 over the Gauss rule
  double correlation =
      0;  ///< Spearman rho of Theta and H on the samples (NaN if either is constant)
  bool distorted = false;    ///< H > 0 somewhere: the element is not the ideal one
  bool affine = false;       ///< W constant over the element
  bool detected = false;     ///< test 1
  bool distributes = false;  ///< test 2 (true on an affine element)
  bool inverted = false;     ///< test 3 failed
  /// The Table 3.2 tick by the full criterion.
  bool represents = false;
  /// The tick by test 1 alone ("detected == distorted").
  bool detects = false;
  /// The tick by tests 1 and 2 (without the inversion test).
  bool detects_and_distributes = false;
};

/// The cell of measure m and gallery element e.
RepresentationCell assess_representation(const Measure& m, const GalleryElement& e,
                                         const RepresentationCriterion& c = {});

/// Every measure (registry order) times every element (gallery order),
/// measure-major.
std::vector<RepresentationCell> distortion_representation(
    const std::vector<GalleryElement>& gallery, const RepresentationCriterion& c = {});

struct TableAgreement {
  int agree = 0;
  int compared = 0;
  std::vector<const RepresentationCell*> disagreements;
};

/// Compares the flag `tick` (&RepresentationCell::represents, or one of the
/// simpler criteria) of every cell that `table` lists (rows = measures,
/// columns = elements) with the thesis's 0/1.
TableAgreement compare_with_thesis(
    const std::vector<RepresentationCell>& cells, const ThesisTable& table,
    bool RepresentationCell::*tick = &RepresentationCell::represents);

}  // namespace homesh
