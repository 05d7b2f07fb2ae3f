#include "pipeline/run_pipeline.h"

#include <gmsh.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/error.h"
#include "core/progress.h"
#include "gmsh/gmsh_call.h"
#include "gmsh/read_model.h"
#include "gmsh/views.h"
#include "gmsh/write_model.h"
#include "gmsh/write_msh.h"
#include "pipeline/quality_report.h"
#include "pipeline/stage_registry.h"
#include "quality/mesh_validity.h"

namespace homesh {
namespace {

std::string extension(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return ext;
}

void check_readable(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) throw Error(path + ": " + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw Error(path + ": not a regular file");
  if (st.st_size == 0) throw Error(path + ": empty file");
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot be read");
}

}  // namespace

void load_input(const std::string& path, Context& ctx) {
  static const std::vector<std::string> kinds = {"geo", "step", "stp", "brep",
                                                 "iges", "igs", "msh"};
  const std::string ext = extension(path);
  if (std::find(kinds.begin(), kinds.end(), ext) == kinds.end())
    throw Error(path + ": unknown input kind '." + ext +
                "' (expected .geo, .step, .stp, .brep, .iges, .igs or .msh)");
  check_readable(path);
  ctx.input = path;
  gmsh_adapter::gmsh_call(path, [&] {
    gmsh::clear();
    gmsh::open(path);
  });
  ctx.has_cad = gmsh_adapter::model_has_cad();
  if (gmsh_adapter::model_has_mesh()) {
    ctx.mesh = gmsh_adapter::read_model(path);
  } else if (ext == "msh") {
    throw Error(path + ": has no triangles (no 2D mesh)");
  } else if (!ctx.has_cad) {
    throw Error(path + ": defines no geometry and no mesh");
  }
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
  if (!ctx.mesh && !meshes) {
    ctx.log.info("{} has no mesh: meshing it with the mesh stage's defaults", ctx.input);
    const Stage& m = stage("mesh");
    m.run(ctx, m.parse({}));
  }
  set_progress(progress_wanted(ctx.log.quiet));
  for (std::size_t k = 0; k < plan.size(); ++k) {
    const Progress stage_label(
        "stage " + std::to_string(k + 1) + "/" + std::to_string(plan.size()) + " " +
            plan[k].first->name,
        0);
    plan[k].first->run(ctx, plan[k].second);
  }
}

void write_output(const std::string& path, const std::string& provenance, Context& ctx) {
  const Mesh& m = ctx.require_mesh("output");
  if (extension(path) != "msh") throw Error(path + ": output must be a .msh file");
  // Every output carries its certified validity; an invalid mesh is never written silently.
  const MeshValidity v = mesh_validity(m);
  if (std::none_of(ctx.fields.begin(), ctx.fields.end(),
                   [](const Field& f) { return f.name == "minJ/maxJ"; })) {
    ctx.log.info("{}", validity_line(m, v));
    ctx.set_field({"minJ/maxJ", Field::Kind::Element, v.ratio.transpose()});
  }
  if (v.invalid > 0 && !ctx.keep_invalid)
    throw Error(path + ": not written: " + std::to_string(v.invalid) +
                " triangles are not certified valid (keep them with --keep-invalid)");
  if (v.invalid > 0) ctx.log.warn("{}: writing {} invalid triangles as asked", path, v.invalid);

  std::vector<int> views;
  gmsh_adapter::gmsh_call("writing " + path, [&] {
    const auto tags = gmsh_adapter::write_model(m);
    views = gmsh_adapter::add_views(ctx.fields, tags);
  });
  std::string record = provenance;
  for (const std::string& note : ctx.notes) record += "\n" + note;
  gmsh_adapter::write_msh(path, views, record);
  ctx.log.info("wrote {} (order {}, {} triangles, {} views)", path, m.order, m.num_triangles(),
               views.size());
}

}  // namespace homesh
