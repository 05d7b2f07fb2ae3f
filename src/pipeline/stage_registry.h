#pragma once
// The one table of pipeline stages, keyed by name: it drives the CLI (`-m`,
// `--list`, `--help STAGE`), the Python API and the tests.
#include <string>
#include <vector>

#include "pipeline/stage.h"

namespace homesh {

/// Every stage, in the order `--list` shows them.
const std::vector<Stage>& stages();

/// The stage called `name`; homesh::Error listing the stages if there is none.
const Stage& stage(const std::string& name);

/// Human-readable help of one stage: summary and options with defaults.
std::string stage_help(const Stage& s);

}  // namespace homesh
