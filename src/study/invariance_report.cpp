#include "study/invariance_report.h"

#include <fmt/format.h>

#include "optim/thesis_tables.h"
#include "quality/measure_registry.h"

namespace homesh {

std::string report_invariance(const StudyInputs& in) {
  const ThesisTable thesis = read_thesis_table(in.reference + "/table_3_7_invariance.csv");
  std::string md =
      "## Table 3.7: invariance (Section 3.7.1)\n\n"
      "Asserted exactly against `table_3_7_invariance.csv` by the quality tests, not repeated "
      "here: `tests/quality/measure_properties_test.cpp` (registry flags = the thesis's; on 2000 "
      "random W no invariant measure changes under scaling or rotation, and more than 98 % of "
      "the samples of each scale-sensitive one do; relabelling the corners rotates W on the "
      "right and changes nothing) and `tests/quality/element_quality_test.cpp` (whole p = 2, 3, "
      "4 elements relabelled, scaled by 3.7 and rotated). Label / scale / rotation, 1 = "
      "invariant:\n\n"
      "| measure | ours | thesis | agree |\n|---|---|---|---|\n";
  int agree = 0;
  for (const Measure& m : measures()) {
    const std::string ours = fmt::format("{} / {} / {}", int(m.invariance.label),
                                         int(m.invariance.scale), int(m.invariance.rotation));
    const std::string theirs =
        fmt::format("{} / {} / {}", thesis.at(m.name, "label"), thesis.at(m.name, "scale"),
                    thesis.at(m.name, "rotation"));
    agree += ours == theirs;
    md +=
        fmt::format("| {} | {} | {} | {} |\n", m.name, ours, theirs, ours == theirs ? "yes" : "NO");
  }
  return md + fmt::format("\n{}/{} measures agree in all three.\n\n", agree, measures().size());
}

}  // namespace homesh
