#pragma once
// Element quality in the presence of boundaries (thesis Section 3.8.3, Fig
// 3.29): which measures give a valid symmetric, valid asymmetric or invalid
// optimal element (optim/boundary_guidance.h), beside the boundary_guidance
// column of tests/data/thesis/table_3_7_invariance.csv.
#include <string>

#include "study/study_output.h"

namespace homesh {

/// Writes boundary_guidance.csv (per measure: the thesis's guidance and ours,
/// PRAXIS's evaluations, f0, f, asymmetry, validity, the best symmetric element
/// by brute force, and the optimal nodes 4 and 5); returns the summary's section.
std::string report_boundary(const StudyInputs& in, const StudyOutput& out);

}  // namespace homesh
