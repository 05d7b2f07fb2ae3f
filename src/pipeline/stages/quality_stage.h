#pragma once
#include "pipeline/stage.h"

namespace homesh {

/// `quality`: certified validity and quality measures as views and a report.
Stage quality_stage();

}  // namespace homesh
