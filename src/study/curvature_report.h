#pragma once
// Sensitivity to boundary-edge curvature (thesis Section 3.8.3, Fig 3.32,
// Table 3.6; optim/curvature_sensitivity.h).
#include <string>

#include "study/study_output.h"

namespace homesh {

/// Writes curvature.csv (chi in [-0.2, 0.2] by 0.01, f of every measure) and
/// returns the summary's section: our sensitivity orderings at chi = -0.2
/// (convex) and 0.2 (concave) beside Table 3.6, and the concave-versus-convex
/// comparison at equal |chi|.
std::string report_curvature(const StudyInputs& in, const StudyOutput& out);

}  // namespace homesh
