#pragma once
// The state a pipeline of stages works on: the input's name, whether the
// current Gmsh model carries CAD, the core mesh (the source of truth once
// read), the fields that become views, numbers a stage reports (returned by
// the Python module as result["results"]), and the log.
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/field.h"
#include "core/mesh.h"
#include "core/volume_mesh.h"
#include "pipeline/log.h"
#include "quality/mesh_validity.h"

namespace homesh {

using ResultValue = std::variant<bool, int, double>;

struct Context {
  std::string input;
  bool has_cad = false;
  std::optional<Mesh> mesh;
  /// A volume mesh (tetrahedra, issue 24), read instead of `mesh` from a model
  /// with 3D elements; the fields are then over its tetrahedra.
  std::optional<VolumeMesh> volume;
  std::vector<Field> fields;
  /// Named results the last stage reports (e.g. rotate's theta_max): counts
  /// as int, flags as bool, measurements as double.
  std::map<std::string, ResultValue> results;
  Log log;
  /// Lines recorded in the output's provenance after the command line: what a
  /// reader of the file must know about how it was made (e.g. that the
  /// boundary was rebuilt without CAD).
  std::vector<std::string> notes;
  /// Write the output even if some element is not certified valid.
  bool keep_invalid = false;
  /// Let a `.geo` input run commands that reach outside the model (System,
  /// Save, ...: gmsh/geo_commands.h); refused otherwise.
  bool trust_geo = false;

  /// A state of `mesh` (its order, nodes and elements only) and its certified
  /// validity, where a stage had them at hand: mesh_validity() reuses its bounds
  /// for the elements still as they were.
  struct Certified {
    Mesh mesh;
    MeshValidity validity;
  };
  std::optional<Certified> certified;

  /// The same for `volume`: a state of its order, nodes and tetrahedra, and
  /// their validity, which volume_validity() reuses where refined by its options.
  struct VolumeCertified {
    VolumeMesh mesh;
    MeshValidity validity;
  };
  std::optional<VolumeCertified> volume_certified;

  /// Records v as the certified validity of the mesh as it is now.
  void certify(MeshValidity v);
  /// Records v as the certified validity of `volume` as it is now.
  void certify_volume(MeshValidity v);
  /// The certified validity of `volume` (default bounds), reusing `volume_certified`.
  MeshValidity volume_validity() const;

  /// The certified validity of the mesh (default bounds), reusing `certified`.
  MeshValidity mesh_validity() const;

  /// Adds `f`, replacing a field of the same name.
  void set_field(Field f);

  /// The mesh, or homesh::Error telling `stage` needs one.
  Mesh& require_mesh(const std::string& stage);

  /// homesh::Error telling `stage` needs CAD geometry to mesh, unless the input has it.
  void require_cad(const std::string& stage) const;
};

}  // namespace homesh
