#pragma once
#include <string>
#include <vector>

#include "curving/rotate_boundary.h"
#include "pipeline/stage.h"

namespace homesh {

/// The rotate stage's options: the wall to turn and the rotation.
struct RotateStageOptions {
  /// Curve physical group names or numbers, or curve tags (core/wall_curves.h).
  std::vector<std::string> wall = {"hole"};
  RotateOptions rotation;
};

/// `rotate`: the rotation benchmark of thesis Section 4.4 on the current mesh:
/// the wall's curves turn rigidly step by step, the interior follows the
/// elastic analogy, until the first step that would make an element invalid;
/// the output is the last valid state, and theta_max, steps, mean CG
/// iterations and the worst minJ/maxJ go to the log and ctx.results.
Stage rotate_stage();

}  // namespace homesh
