#pragma once
// A pipeline stage: a named transformation of the Context, with the table of
// its options (pipeline/option_table.h; NekMesh-style modules). A stage is a
// thin adapter: `parse` reads the user's strings into the options struct of
// its library entry point (before any stage runs, so a bad option fails
// fast), `run` adapts the Gmsh model to that entry point.
#include <any>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/error.h"
#include "pipeline/context.h"
#include "pipeline/option_table.h"
#include "pipeline/options.h"

namespace homesh {

struct Stage {
  std::string name;
  std::string summary;
  /// The options with their defaults, from the stage's option table.
  std::vector<OptionSpec> options;
  /// The given options read into the stage's options struct (held in the
  /// std::any); homesh::Error naming the stage, option and value if refused.
  std::function<std::any(const std::map<std::string, std::string>& given)> parse;
  /// Runs the stage with options made by `parse`.
  std::function<void(Context&, const std::any& options)> run;
  /// The stage makes a new mesh from the CAD (so none is needed before it).
  bool creates_mesh = false;
  /// The stage works on meshes holding quadrilaterals; run_stage refuses
  /// such a mesh to every other stage, so none drops or mangles them silently.
  bool handles_quads = false;
  /// The stage works on volume meshes (tetrahedra, issue 24); run_stage
  /// refuses one to every other stage.
  bool handles_volumes = false;
};

/// Runs stage s on ctx with options made by s.parse. Throws homesh::Error
/// naming the stage and the element type, before the stage does anything, if
/// ctx's mesh holds quadrilaterals and s does not handle them, or ctx holds a
/// volume mesh and s does not handle one.
inline void run_stage(const Stage& s, Context& ctx, const std::any& options) {
  if (!s.handles_volumes && ctx.volume)
    throw Error("stage '" + s.name + "' does not handle tetrahedra yet (mesh has " +
                std::to_string(ctx.volume->num_tetrahedra()) + " '" +
                tetrahedron_type_name(ctx.volume->order) + "')");
  if (!s.handles_quads && ctx.mesh && ctx.mesh->num_quads() > 0)
    throw Error("stage '" + s.name + "' does not handle quadrilaterals yet (mesh has " +
                std::to_string(ctx.mesh->num_quads()) + " '" + quad_type_name(ctx.mesh->order) +
                "')");
  s.run(ctx, options);
}

/// The options struct of a stage without options.
struct NoOptions {};

/// The stage called `name` whose options are read by `table` into a T and
/// passed to `run`.
template <class T>
Stage make_stage(std::string name, std::string summary, const OptionTable<T>& table,
                 void (*run)(Context&, const T&), bool creates_mesh = false,
                 bool handles_quads = false, bool handles_volumes = false) {
  Stage s;
  s.name = name;
  s.summary = std::move(summary);
  s.options = table.specs();
  s.parse = [table, name](const std::map<std::string, std::string>& given) {
    return std::any(table.parse(name, given));
  };
  s.run = [run](Context& ctx, const std::any& options) {
    run(ctx, std::any_cast<const T&>(options));
  };
  s.creates_mesh = creates_mesh;
  s.handles_quads = handles_quads;
  s.handles_volumes = handles_volumes;
  return s;
}

}  // namespace homesh
