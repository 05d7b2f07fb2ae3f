#include "pipeline/analogy_options.h"

namespace homesh {

std::vector<std::string> formulation_names() {
  std::vector<std::string> names;
  for (const auto& f : analogy_formulations()) names.push_back(f.name);
  return names;
}

}  // namespace homesh
