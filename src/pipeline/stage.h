#pragma once
// A pipeline stage: a named transformation of the Context, declaring its
// options with defaults and help (NekMesh-style modules).
#include <functional>
#include <string>
#include <vector>

#include "pipeline/context.h"
#include "pipeline/options.h"

namespace homesh {

struct Stage {
  std::string name;
  std::string summary;
  std::vector<OptionSpec> options;
  std::function<void(Context&, const Options&)> run;
  /// The stage makes a new mesh from the CAD (so none is needed before it).
  bool creates_mesh = false;
};

}  // namespace homesh
