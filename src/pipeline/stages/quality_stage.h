#pragma once
#include <string>
#include <vector>

#include "pipeline/stage.h"
#include "quality/jacobian_bounds.h"
#include "quality/mesh_quality.h"

namespace homesh {

/// What the quality stage computes (quality/mesh_quality.h) and reports.
struct QualityOptions {
  std::vector<std::string> measures = {"Q4", "Q17", "Q11"};  ///< names of measures()
  Reference reference = Reference::element_max;              ///< the thesis' normalisation
  int lattice = 0;  ///< sampling lattice order; 0: default_lattice_order(p)
  BoundsOptions bounds;
  int worst = 5;      ///< worst elements listed
  double poor = 0.5;  ///< elements of certified minJ/maxJ below this get a view of their own
  int threads = 0;    ///< 0: one per core
};

/// `quality`: certified validity and quality measures as views and a report.
Stage quality_stage();

}  // namespace homesh
