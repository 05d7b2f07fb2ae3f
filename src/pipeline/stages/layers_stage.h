#pragma once
#include "pipeline/stage.h"

namespace homesh {

/// `layers`: boundary layers on chosen walls (thesis Section 4.3): the room is
/// opened by the elastic analogy, then filled with geometric layers along single
/// or multiple normals; the radius ratio of Eq 4.17 is reported and kept as a view.
Stage layers_stage();

}  // namespace homesh
