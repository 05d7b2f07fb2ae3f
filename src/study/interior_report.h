#pragma once
// Optimal interior elements (thesis Section 3.8.2, Tables 3.3-3.5): PRAXIS
// and brute force for every measure on the quadratic and cubic cases
// (optim/interior_optimum.h), iteration counts beside the thesis's.
#include <string>

#include "study/study_output.h"

namespace homesh {

/// Writes interior_optimum.csv (per measure and case: the thesis's N, our
/// PRAXIS evaluations, f0, f and error of PRAXIS and of the grid),
/// praxis_histories.csv (case,measure,evaluation,f) and interior_landscape.csv
/// (f of Q2 and Q8 over positions of the quadratic case's free node, as Fig
/// 3.27(d), (f)); returns the summary's section.
std::string report_interior(const StudyInputs& in, const StudyOutput& out);

}  // namespace homesh
