#include "pipeline/context.h"

#include "core/error.h"
#include "quality/volume_validity.h"

namespace homesh {

Mesh& Context::require_mesh(const std::string& stage) {
  if (!mesh)
    throw Error("stage '" + stage + "': " + input + " has no mesh (run the mesh stage first)");
  return *mesh;
}

void Context::require_cad(const std::string& stage) const {
  if (!has_cad)
    throw Error("stage '" + stage + "': " + input +
                " has no CAD geometry to mesh (give a .geo, .step or .brep)");
}

void Context::certify(MeshValidity v) {
  const Mesh& m = require_mesh("certify");
  Certified c;
  c.mesh.order = m.order;  // what mesh_validity's reuse compares, not the classes and groups
  c.mesh.x = m.x;
  c.mesh.tri = m.tri;
  c.mesh.quad = m.quad;
  c.validity = std::move(v);
  certified = std::move(c);
}

void Context::certify_volume(MeshValidity v) {
  if (!volume) throw Error("the certified validity of " + input + ": no tetrahedra");
  VolumeCertified c;
  c.mesh.order = volume->order;  // what volume_validity's reuse compares
  c.mesh.x = volume->x;
  c.mesh.tet = volume->tet;
  c.validity = std::move(v);
  volume_certified = std::move(c);
}

MeshValidity Context::volume_validity() const {
  if (!volume) throw Error("the certified validity of " + input + ": no tetrahedra");
  if (!volume_certified) return homesh::volume_validity(*volume);
  return homesh::volume_validity(*volume, volume_certified->mesh, volume_certified->validity);
}

MeshValidity Context::mesh_validity() const {
  if (!mesh) throw Error("the certified validity of " + input + ": no mesh");
  if (!certified) return homesh::mesh_validity(*mesh);
  return homesh::mesh_validity(*mesh, certified->mesh, certified->validity);
}

void Context::set_field(Field f) {
  for (Field& g : fields)
    if (g.name == f.name) {
      g = std::move(f);
      return;
    }
  fields.push_back(std::move(f));
}

}  // namespace homesh
