#pragma once
// Thesis Table 3.2 reproduced on our gallery (optim/distortion_representation.h)
// and compared cell by cell with tests/data/thesis/table_3_2_distortion_representation.csv.
#include <string>

#include "study/study_output.h"

namespace homesh {

/// Writes table_3_2_ours.csv (our ticks, laid out as the thesis's table),
/// table_3_2_cells.csv (every cell: thesis, ours, the criterion's numbers) and
/// table_3_2_note.md (the criterion, the agreement and an explanation of every
/// disagreement); returns the summary's section.
std::string report_representation(const StudyInputs& in, const StudyOutput& out);

}  // namespace homesh
