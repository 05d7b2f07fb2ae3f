#include "quality/mesh_validity.h"

#include "quality/mesh_quality.h"

namespace homesh {

MeshValidity mesh_validity(const Mesh& m, const BoundsOptions& opt) {
  return mesh_quality(m, {}, 0, Reference::ideal, opt).validity;
}

}  // namespace homesh
