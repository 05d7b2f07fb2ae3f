#pragma once
// Normalisation of the size-sensitive measures to [0, 1] (thesis Section 3.7).
//
// The raw measures Q2, Q3, Q4, Q5, Q9, Q10 and Q17 of Table 3.1 are energies or
// ratios with no upper bound whose value at the ideal element (W = I) is q*.
// They are mapped to quality by folding the ratio x = q / q* onto (0, 1]:
//
//   Q = min(x, 1/x),   Theta = 1/Q - 1 = max(x, 1/x) - 1   (Eq 3.49),
//
// so growth and shrinkage by the same factor cost the same, Q = 1 exactly where
// the raw measure takes its ideal value, and Q -> 0 as q -> 0 or q -> infinity.
// The thesis instead divides by the largest value over the element
// (Q / Qmax, text after Eq 3.49): element_quality.h offers that as
// Reference::element_max.

namespace homesh {

/// min(q / q_ideal, q_ideal / q) for q > 0, and 0 for q <= 0; q_ideal > 0.
inline double ratio_quality(double q, double q_ideal) {
  if (!(q > 0.0)) return 0.0;
  const double x = q / q_ideal;
  return x < 1.0 ? x : 1.0 / x;
}

}  // namespace homesh
