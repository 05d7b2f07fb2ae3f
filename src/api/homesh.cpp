#include "api/homesh.h"

#include <gmsh.h>

#include "core/progress.h"
#include "gmsh/gmsh_call.h"
#include "gmsh/read_model.h"
#include "gmsh/views.h"
#include "gmsh/write_model.h"
#include "gmsh/write_msh.h"
#include "pipeline/context.h"
#include "pipeline/quality_report.h"
#include "pipeline/stage_registry.h"
#include "quality/mesh_validity.h"

namespace homesh::api {
namespace {

bool quiet_ = false;

Validity summary(const Mesh& m) {
  const MeshValidity v = mesh_validity(m);
  return {m.num_triangles(), v.invalid, v.worst, v.worst_element + 1, validity_line(m, v)};
}

// Runs `body`, Gmsh's own std::string throws turned into homesh::Error as the CLI reports them.
template <typename Body>
auto guarded(Body body) {
  try {
    return body();
  } catch (const std::string& e) {
    throw Error("Gmsh: " + e);
  }
}

}  // namespace

std::vector<StageInfo> stages() {
  std::vector<StageInfo> out;
  for (const Stage& s : homesh::stages()) {
    StageInfo info{s.name, s.summary, {}, stage_help(s)};
    for (const OptionSpec& o : s.options) info.options.push_back({o.name, o.default_value, o.help});
    out.push_back(std::move(info));
  }
  return out;
}

Result run(const std::string& name, const StageOptions& options) {
  return guarded([&] {
    const Stage& s = stage(name);
    const Options checked(s.name, s.options, options);
    Context ctx;
    ctx.input = "the current Gmsh model";
    ctx.log.quiet = quiet_;
    ctx.has_cad = gmsh_adapter::model_has_cad();
    if (gmsh_adapter::model_has_mesh()) ctx.mesh = gmsh_adapter::read_model(ctx.input);
    set_progress(progress_wanted(quiet_));
    {
      const Progress label(s.name, 0);
      s.run(ctx, checked);
    }

    Result r;
    r.results = ctx.results;
    if (!ctx.mesh) return r;
    gmsh_adapter::gmsh_call("writing the mesh into the current Gmsh model", [&] {
      r.views = gmsh_adapter::add_views(ctx.fields, gmsh_adapter::write_model(*ctx.mesh));
    });
    r.has_mesh = true;
    r.order = ctx.mesh->order;
    r.nodes = ctx.mesh->num_nodes();
    r.triangles = ctx.mesh->num_triangles();
    r.validity = summary(*ctx.mesh);
    return r;
  });
}

Result mesh(const StageOptions& options) { return run("mesh", options); }
Result order(const StageOptions& options) { return run("order", options); }
Result layers(const StageOptions& options) { return run("layers", options); }
Result curve(const StageOptions& options) { return run("curve", options); }
Result optimise(const StageOptions& options) { return run("optimise", options); }
Result rotate(const StageOptions& options) { return run("rotate", options); }
Result quality(const StageOptions& options) { return run("quality", options); }
Result info(const StageOptions& options) { return run("info", options); }
Result voronoi(const StageOptions& options) { return run("voronoi", options); }

Validity validity() {
  return guarded([] {
    const std::string source = "the current Gmsh model";
    if (!gmsh_adapter::model_has_mesh()) throw Error(source + ": has no triangles (no 2D mesh)");
    return summary(gmsh_adapter::read_model(source));
  });
}

void write(const std::string& path, const std::string& provenance) {
  guarded([&] {
    std::vector<int> views;
    gmsh::view::getTags(views);
    gmsh_adapter::write_msh(path, views, provenance);
  });
}

void set_quiet(bool quiet) { quiet_ = quiet; }

}  // namespace homesh::api
