#include "api/homesh.h"

#include <gmsh.h>

#include <algorithm>

#include "core/progress.h"
#include "gmsh/gmsh_call.h"
#include "gmsh/line_tags.h"
#include "gmsh/option_scope.h"
#include "gmsh/read_model.h"
#include "gmsh/read_views.h"
#include "gmsh/read_volume_model.h"
#include "gmsh/view_style.h"
#include "gmsh/views.h"
#include "gmsh/write_model.h"
#include "gmsh/write_msh.h"
#include "gmsh/write_volume_model.h"
#include "io/write_vtu.h"
#include "pipeline/context.h"
#include "pipeline/group_context_by_entity.h"
#include "pipeline/output_format.h"
#include "pipeline/quality_report.h"
#include "pipeline/stage_registry.h"
#include "quality/mesh_validity.h"
#include "quality/volume_validity.h"

namespace homesh::api {
namespace {

bool quiet_ = false;
LogSink sink_;

// The stages' log as the caller set it up: set_quiet, the sink, and Gmsh's
// General.Verbosity (below 4: no info; below 2: no warnings either), as
// Gmsh's own messages follow it.
void configure_log(Log& log) {
  double verbosity = 5;
  gmsh::option::getNumber("General.Verbosity", verbosity);
  log.quiet = quiet_ || verbosity < 4;
  log.silent = verbosity < 2;
  if (sink_)
    log.sink = [](LogLevel level, const std::string& text) {
      sink_(level == LogLevel::Info ? 0 : 1, text);
    };
}

// The mesh's validity, its worst triangle named by the Gmsh tag homesh
// writes it with (Mesh::triangle_tag), or by `tags` when read from a model.
Validity summary(const Mesh& m, const MeshValidity& v, const std::vector<std::size_t>& tags = {}) {
  const std::size_t worst = v.worst_element < 0 ? 0
                            : tags.empty()      ? m.triangle_tag(v.worst_element)
                                                : tags[static_cast<std::size_t>(v.worst_element)];
  return {m.num_triangles(),         m.num_quads(), 0, v.invalid, v.worst, static_cast<int>(worst),
          validity_line(m, v, worst)};
}

Validity summary(const Mesh& m, const std::vector<std::size_t>& tags = {}) {
  return summary(m, mesh_validity(m), tags);
}

// The validity of a volume mesh (issue 24), its worst tetrahedron named by the
// tag homesh writes it with, or by `tags` when read from a model.
Validity summary(const VolumeMesh& m, const MeshValidity& v,
                 const std::vector<std::size_t>& tags = {}) {
  const std::size_t worst = v.worst_element < 0 ? 0
                            : tags.empty()      ? m.tetrahedron_tag(v.worst_element)
                                                : tags[static_cast<std::size_t>(v.worst_element)];
  Validity r{
      m.num_triangles(),         0, m.num_tetrahedra(), v.invalid, v.worst, static_cast<int>(worst),
      validity_line(m, v, worst)};
  return r;
}

// Runs `body`, Gmsh's own std::string throws turned into homesh::Error as the
// CLI reports them. Gmsh errors are logged, not thrown, meanwhile: a throw
// from inside one of Gmsh's OpenMP regions would abort the user's process.
template <typename Body>
auto guarded(Body body) {
  try {
    gmsh_adapter::OptionScope options;
    options.set("General.AbortOnError", 0);
    return body();
  } catch (const std::string& e) {
    throw Error("Gmsh: " + e);
  }
}

// api::write of the model's volume mesh (issue 24): the .msh as Gmsh holds it
// (its views with it), or a .vtu of the mesh and its certified minJ/maxJ.
void write_volume(const std::string& path, OutputFormat format, const std::string& source,
                  const std::string& provenance, bool keep_invalid) {
  std::vector<std::size_t> tags;
  const VolumeMesh m = gmsh_adapter::read_volume_model(source, &tags);
  const MeshValidity certified = volume_validity(m);
  const Validity v = summary(m, certified, tags);
  if (v.invalid > 0 && !keep_invalid)
    throw Error(path + ": not written: " + std::to_string(v.invalid) +
                " tetrahedra are not certified valid (keep them with keep_invalid)");
  if (format == OutputFormat::vtu) {
    // The model's views are over Gmsh's own element tags; the .vtu carries the certificate.
    const Field ratio{kValidityFieldName, Field::Kind::Element, certified.ratio.transpose()};
    write_vtu(path, m, {ratio}, provenance + "\n" + v.line, tags);
    return;
  }
  std::vector<int> views;
  gmsh::view::getTags(views);
  gmsh_adapter::write_msh(path, views, provenance + "\n" + v.line);
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
    const std::any checked = s.parse(options);
    Context ctx;
    ctx.input = "the current Gmsh model";
    configure_log(ctx.log);
    ctx.has_cad = gmsh_adapter::model_has_cad();
    if (gmsh_adapter::model_has_volume_mesh())
      ctx.volume = gmsh_adapter::read_volume_model(ctx.input);
    else if (gmsh_adapter::model_has_mesh())
      ctx.mesh = gmsh_adapter::read_model(ctx.input);
    set_progress(progress_wanted(ctx.log.quiet));
    {
      const Progress label(s.name, 0);
      run_stage(s, ctx, checked);
      group_context_by_entity(ctx);
    }

    Result r;
    r.results = ctx.results;
    if (ctx.volume) {
      const VolumeMesh& m = *ctx.volume;
      gmsh_adapter::gmsh_call("writing the mesh into the current Gmsh model", [&] {
        r.views = gmsh_adapter::add_views(ctx.fields, gmsh_adapter::write_volume_model(m));
        if (m.order > 1) gmsh_adapter::draw_edges_curved();
      });
      r.has_mesh = true;
      r.order = m.order;
      r.nodes = m.num_nodes();
      r.triangles = m.num_triangles();
      r.tetrahedra = m.num_tetrahedra();
      r.validity = summary(m, ctx.volume_validity());
      return r;
    }
    if (!ctx.mesh) return r;
    gmsh_adapter::gmsh_call("writing the mesh into the current Gmsh model", [&] {
      r.views = gmsh_adapter::add_views(ctx.fields, gmsh_adapter::write_model(*ctx.mesh));
      if (ctx.mesh->order > 1) gmsh_adapter::draw_edges_curved();  // as opening the file does
    });
    r.has_mesh = true;
    r.order = ctx.mesh->order;
    r.nodes = ctx.mesh->num_nodes();
    r.triangles = ctx.mesh->num_triangles();
    r.quadrilaterals = ctx.mesh->num_quads();
    r.validity = summary(*ctx.mesh, ctx.mesh_validity());
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
    if (gmsh_adapter::model_has_volume_mesh()) {
      std::vector<std::size_t> tags;
      const VolumeMesh m = gmsh_adapter::read_volume_model(source, &tags);
      return summary(m, volume_validity(m), tags);
    }
    if (!gmsh_adapter::model_has_mesh()) throw Error(source + ": has no triangles (no 2D mesh)");
    std::vector<std::size_t> tags;
    const Mesh m = gmsh_adapter::read_model(source, &tags);
    return summary(m, tags);
  });
}

void write(const std::string& path, const std::string& provenance, bool keep_invalid) {
  guarded([&] {
    const OutputFormat format = check_output_path(path);
    // Every output carries its certified validity; an invalid mesh is never written silently.
    const std::string source = "the current Gmsh model";
    if (gmsh_adapter::model_has_volume_mesh())
      return write_volume(path, format, source, provenance, keep_invalid);
    if (!gmsh_adapter::model_has_mesh()) throw Error(source + ": has no triangles (no 2D mesh)");
    std::vector<std::size_t> tags;
    const Mesh m = gmsh_adapter::read_model(source, &tags);
    const MeshValidity certified = mesh_validity(m);
    const Validity v = summary(m, certified, tags);
    if (v.invalid > 0 && !keep_invalid)
      throw Error(path + ": not written: " + std::to_string(v.invalid) +
                  (m.num_quads() > 0 ? " elements" : " triangles") +
                  " are not certified valid (keep them with keep_invalid)");
    if (format == OutputFormat::vtu) {
      // The views become the .vtu's fields; the certified minJ/maxJ is always one of them.
      std::vector<Field> fields = gmsh_adapter::read_views(m, tags);
      if (std::none_of(fields.begin(), fields.end(),
                       [](const Field& f) { return f.name == kValidityFieldName; }))
        fields.push_back({kValidityFieldName, Field::Kind::Element, certified.ratio.transpose()});
      write_vtu(path, m, fields, provenance + "\n" + v.line, {tags, gmsh_adapter::line_tags(m)});
      return;
    }
    std::vector<int> views;
    gmsh::view::getTags(views);
    gmsh_adapter::write_msh(path, views, provenance + "\n" + v.line);
  });
}

void set_quiet(bool quiet) { quiet_ = quiet; }

void set_log_sink(LogSink sink) { sink_ = std::move(sink); }

}  // namespace homesh::api
