#include "pipeline/run_pipeline.h"

#include <fmt/core.h>
#include <gmsh.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>

#include "core/error.h"
#include "core/file_extension.h"
#include "core/group_by_entity.h"
#include "core/input_limits.h"
#include "core/progress.h"
#include "gmsh/exit_guard.h"
#include "gmsh/geo_commands.h"
#include "gmsh/gmsh_call.h"
#include "gmsh/msh_header.h"
#include "gmsh/read_in_child.h"
#include "gmsh/read_model.h"
#include "gmsh/read_volume_model.h"
#include "gmsh/views.h"
#include "gmsh/write_model.h"
#include "gmsh/write_msh.h"
#include "gmsh/write_volume_model.h"
#include "io/write_vtu.h"
#include "pipeline/group_context_by_entity.h"
#include "pipeline/output_format.h"
#include "pipeline/quality_report.h"
#include "pipeline/stage_registry.h"
#include "quality/mesh_validity.h"
#include "quality/volume_validity.h"

namespace homesh {
namespace {

void check_readable(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) throw Error(path + ": " + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw Error(path + ": not a regular file");
  if (st.st_size == 0) throw Error(path + ": empty file");
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot be read");
}

// Commands that reach outside the model (running programs, writing files,
// sleeping) need --trust-geo.
void check_geo_commands(const std::string& path, bool trusted) {
  if (trusted) return;
  for (const auto& c : gmsh_adapter::geo_file_commands(path)) {
    const std::string at = c.file + ":" + std::to_string(c.line);
    const bool computed = c.name == "Include" || c.name == "Merge";
    throw Error(at + ": " +
                (computed ? "'" + c.name + "' of a computed path, which homesh cannot check"
                          : "the command '" + c.name + "' reaches outside the model") +
                "; homesh runs such .geo files only with --trust-geo");
  }
}

// Gmsh's reader drops some elements without an error (a P1 and a P2 triangle
// in one entity keep one kind): what it read must be all the file declares.
// (Nodes no element uses are dropped too, harmlessly: they are not compared.)
void check_nothing_dropped(const std::string& path) {
  const gmsh_adapter::MshHeader h = gmsh_adapter::read_msh_header(path);
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
  gmsh::model::mesh::getElements(types, element_tags, element_nodes, -1, -1);
  std::uint64_t elements = 0;
  for (const auto& t : element_tags) elements += t.size();
  if (h.elements && *h.elements != elements)
    throw Error(path + ": the file declares " + std::to_string(*h.elements) +
                " elements, but Gmsh read " + std::to_string(elements) +
                " (repeated tags, or element kinds mixed in one entity?)");
}

// A model beyond the input limits (core/input_limits.h) makes Gmsh's meshers
// hang or overflow: refused before any meshing.
void check_model_extent(const std::string& path) {
  double x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, z1 = 0;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  const double far = std::max(
      {std::abs(x0), std::abs(y0), std::abs(z0), std::abs(x1), std::abs(y1), std::abs(z1)});
  const double across = std::hypot(x1 - x0, y1 - y0, z1 - z0);
  if (!std::isfinite(far) || far > limits::kMaxCoordinate)
    throw Error(path + ": the model reaches " + fmt::format("{:g}", far) +
                " from the origin; homesh accepts coordinates up to " +
                fmt::format("{:g}", limits::kMaxCoordinate));
  if (!(across >= limits::kMinExtent && across >= limits::kMinRelativeExtent * far))
    throw Error(
        path + ": the model is " + fmt::format("{:g}", across) +
        " across, too small to mesh where it lies (at least " +
        fmt::format("{:g}", std::max(limits::kMinExtent, limits::kMinRelativeExtent * far)) + ")");
}

}  // namespace

void load_input(const std::string& path, Context& ctx) {
  static const std::vector<std::string> kinds = {"geo",  "step", "stp", "brep",
                                                 "iges", "igs",  "msh"};
  const std::string ext = file_extension(path);
  if (std::find(kinds.begin(), kinds.end(), ext) == kinds.end())
    throw Error(path + ": unknown input kind '." + ext +
                "' (expected .geo, .step, .stp, .brep, .iges, .igs or .msh)");
  check_readable(path);
  if (ext == "geo") check_geo_commands(path, ctx.trust_geo);
  ctx.input = path;
  const auto read = [&] {
    {
      const gmsh_adapter::ExitGuard guard(path);
      gmsh_adapter::gmsh_call(path, [&] {
        gmsh::clear();
        gmsh::open(path);
      });
    }
    if (ext == "msh") check_nothing_dropped(path);
    ctx.has_cad = gmsh_adapter::model_has_cad();
    if (ctx.has_cad) check_model_extent(path);
    if (gmsh_adapter::model_has_volume_mesh()) {
      ctx.volume = gmsh_adapter::read_volume_model(path);
    } else if (gmsh_adapter::model_has_mesh()) {
      ctx.mesh = gmsh_adapter::read_model(path);
      group_by_entity(*ctx.mesh);  // as after every stage: elements tagged in file order
    } else if (ext == "msh") {
      throw Error(path + ": has no triangles (no 2D mesh)");
    } else if (!ctx.has_cad) {
      throw Error(path + ": defines no geometry and no mesh");
    }
  };
  if (ext == "msh") {
    gmsh_adapter::check_element_node_tags(path);
    gmsh_adapter::read_in_child(path, read);
  }
  read();
}

void run_stages(const std::vector<StageCall>& calls, Context& ctx) {
  // Every stage's options read into its options struct first, so a typo or a
  // bad value fails before any work.
  std::vector<std::pair<const Stage*, std::any>> plan;
  for (const StageCall& c : calls) {
    const Stage& s = stage(c.name);
    plan.emplace_back(&s, s.parse(c.given));
  }
  const bool meshes = std::any_of(plan.begin(), plan.end(),
                                  [](const auto& step) { return step.first->creates_mesh; });
  if (!ctx.mesh && !ctx.volume && !meshes) {
    ctx.log.info("{} has no mesh: meshing it with the mesh stage's defaults", ctx.input);
    const Stage& m = stage("mesh");
    run_stage(m, ctx, m.parse({}));
  }
  set_progress(progress_wanted(ctx.log.quiet));
  for (std::size_t k = 0; k < plan.size(); ++k) {
    const Progress stage_label("stage " + std::to_string(k + 1) + "/" +
                                   std::to_string(plan.size()) + " " + plan[k].first->name,
                               0);
    run_stage(*plan[k].first, ctx, plan[k].second);
    group_context_by_entity(ctx);
  }
}

namespace {

// write_output of a volume mesh (issue 24).
void write_volume_output(const std::string& path, const std::string& provenance, Context& ctx) {
  const VolumeMesh& m = *ctx.volume;
  const OutputFormat format = check_output_path(path);
  // Every output carries its certified validity; an invalid mesh is never written silently.
  const MeshValidity v = ctx.volume_validity();
  if (std::none_of(ctx.fields.begin(), ctx.fields.end(),
                   [](const Field& f) { return f.name == kValidityFieldName; })) {
    ctx.log.info("{}", validity_line(m, v));
    ctx.set_field({kValidityFieldName, Field::Kind::Element, v.ratio.transpose(), true, true});
  }
  if (v.invalid > 0 && !ctx.keep_invalid)
    throw Error(path + ": not written: " + std::to_string(v.invalid) +
                " tetrahedra are not certified valid (keep them with --keep-invalid)");
  if (v.invalid > 0) ctx.log.warn("{}: writing {} invalid tetrahedra as asked", path, v.invalid);

  std::string record = provenance;
  for (const std::string& note : ctx.notes) record += "\n" + note;
  if (format == OutputFormat::vtu) {
    write_vtu(path, m, ctx.fields, record);
    ctx.log.info("wrote {} (order {}, {} tetrahedra, {} fields)", path, m.order, m.num_tetrahedra(),
                 ctx.fields.size());
    return;
  }
  std::vector<int> views;
  gmsh_adapter::gmsh_call("writing " + path, [&] {
    views = gmsh_adapter::add_views(ctx.fields, gmsh_adapter::write_volume_model(m));
  });
  gmsh_adapter::write_msh(path, views, record);
  ctx.log.info("wrote {} (order {}, {} tetrahedra, {} triangles, {} views)", path, m.order,
               m.num_tetrahedra(), m.num_triangles(), views.size());
}

}  // namespace

void write_output(const std::string& path, const std::string& provenance, Context& ctx) {
  if (ctx.volume) return write_volume_output(path, provenance, ctx);
  const Mesh& m = ctx.require_mesh("output");
  const OutputFormat format = check_output_path(path);
  // Every output carries its certified validity; an invalid mesh is never written silently.
  const MeshValidity v = ctx.mesh_validity();
  if (std::none_of(ctx.fields.begin(), ctx.fields.end(),
                   [](const Field& f) { return f.name == kValidityFieldName; })) {
    ctx.log.info("{}", validity_line(m, v));
    ctx.set_field({kValidityFieldName, Field::Kind::Element, v.ratio.transpose(), true, true});
  }
  const std::string elements = m.num_quads() > 0 ? "elements" : "triangles";
  if (v.invalid > 0 && !ctx.keep_invalid)
    throw Error(path + ": not written: " + std::to_string(v.invalid) + " " + elements +
                " are not certified valid (keep them with --keep-invalid)");
  if (v.invalid > 0) ctx.log.warn("{}: writing {} invalid {} as asked", path, v.invalid, elements);

  std::string record = provenance;
  for (const std::string& note : ctx.notes) record += "\n" + note;
  const std::string quads =
      m.num_quads() > 0 ? fmt::format(", {} quadrilaterals", m.num_quads()) : "";
  if (format == OutputFormat::vtu) {
    write_vtu(path, m, ctx.fields, record);
    ctx.log.info("wrote {} (order {}, {} triangles{}, {} fields)", path, m.order, m.num_triangles(),
                 quads, ctx.fields.size());
    return;
  }

  std::vector<int> views;
  gmsh_adapter::gmsh_call("writing " + path, [&] {
    const auto tags = gmsh_adapter::write_model(m);
    views = gmsh_adapter::add_views(ctx.fields, tags);
  });
  gmsh_adapter::write_msh(path, views, record);
  ctx.log.info("wrote {} (order {}, {} triangles{}, {} views)", path, m.order, m.num_triangles(),
               quads, views.size());
}

}  // namespace homesh
