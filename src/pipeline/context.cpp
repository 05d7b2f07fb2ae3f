#include "pipeline/context.h"

#include "core/error.h"

namespace homesh {

Mesh& Context::require_mesh(const std::string& stage) {
  if (!mesh) throw Error("stage '" + stage + "': " + input + " has no mesh (run the mesh stage first)");
  return *mesh;
}

}  // namespace homesh
