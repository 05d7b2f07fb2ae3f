#pragma once
// Thesis Table 3.7, invariance rows: label, scale and rotation invariance of
// every measure. They are asserted by the quality tests, not recomputed here:
// tests/quality/measure_properties_test.cpp ("scale and rotation invariance
// match thesis Table 3.7" on 2000 random W, "relabelling the ideal triangle's
// corners rotates W on the right") and tests/quality/element_quality_test.cpp
// (relabelled p = 2, 3, 4 elements, scaled and rotated curved elements).
#include <string>

#include "study/study_output.h"

namespace homesh {

/// The summary's section: the registry's invariance flags beside the thesis's
/// tests/data/thesis/table_3_7_invariance.csv, and where the tests assert them.
std::string report_invariance(const StudyInputs& in);

}  // namespace homesh
