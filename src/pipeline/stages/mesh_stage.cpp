#include "pipeline/stages/mesh_stage.h"

#include <fmt/core.h>
#include <gmsh.h>

#include <chrono>
#include <cmath>
#include <utility>
#include <vector>

#include "gmsh/generate_in_child.h"
#include "gmsh/gmsh_call.h"
#include "gmsh/option_scope.h"
#include "gmsh/read_model.h"
#include "gmsh/read_volume_model.h"

namespace homesh {
namespace {

// Gmsh's 2D algorithms that make triangles (Mesh.Algorithm numbers).
// "model": the model's own (0: not set).
const std::vector<std::pair<std::string, int>> kAlgorithms = {
    {"model", 0}, {"meshadapt", 1}, {"auto", 2}, {"delaunay", 5}, {"frontal", 6}, {"bamg", 7}};

// True if the current model has volumes: the mesh stage then makes tetrahedra.
bool model_has_volumes() {
  gmsh::vectorpair volumes;
  gmsh::model::getEntities(volumes, 3);
  return !volumes.empty();
}

void run(Context& ctx, const MeshOptions& o) {
  ctx.require_cad("mesh");
  if (model_has_volumes()) {
    ctx.mesh.reset();
    ctx.volume = gmsh_volume_mesh(ctx.input, o);
    ctx.fields.clear();
    ctx.log.info("mesh: {} nodes, {} tetrahedra, {} surface triangles, {} lines",
                 ctx.volume->num_nodes(), ctx.volume->num_tetrahedra(), ctx.volume->num_triangles(),
                 ctx.volume->num_lines());
    return;
  }
  ctx.volume.reset();
  ctx.mesh = gmsh_mesh(ctx.input, o);
  ctx.fields.clear();
  ctx.log.info(
      "mesh: {} nodes, {} triangles{}, {} boundary lines", ctx.mesh->num_nodes(),
      ctx.mesh->num_triangles(),
      ctx.mesh->num_quads() > 0 ? fmt::format(", {} quadrilaterals", ctx.mesh->num_quads()) : "",
      ctx.mesh->num_lines());
}

// Runs Gmsh's mesher on the current model with o's options, to dimension `dim`.
void generate(const std::string& input, const MeshOptions& o, int dim) {
  // The user's Gmsh options come back when the mesh is read: a script that
  // calls homesh.mesh(factor=0.5) and then Gmsh's own generate gets its own.
  gmsh_adapter::OptionScope options;
  gmsh_adapter::gmsh_call("stage 'mesh' on " + input, [&] {
    if (o.algorithm > 0) options.set("Mesh.Algorithm", o.algorithm);
    if (o.size_min > 0) options.set("Mesh.MeshSizeMin", o.size_min);
    if (o.size_max > 0) options.set("Mesh.MeshSizeMax", o.size_max);
    if (o.factor > 0) options.set("Mesh.MeshSizeFactor", o.factor);
    options.set("Mesh.ElementOrder", 1);
    options.set("Mesh.RecombineAll", 0);
  });
  gmsh_adapter::generate_in_child(
      input, {static_cast<std::size_t>(o.max_triangles),
              {gmsh_adapter::default_memory_cap(),
               std::chrono::seconds(static_cast<long>(std::ceil(o.max_seconds)))},
              dim});
}

}  // namespace

Mesh gmsh_mesh(const std::string& input, const MeshOptions& o) {
  generate(input, o, 2);
  return gmsh_adapter::read_model(input);
}

VolumeMesh gmsh_volume_mesh(const std::string& input, const MeshOptions& o) {
  generate(input, o, 3);
  return gmsh_adapter::read_volume_model(input);
}

Stage mesh_stage() {
  std::vector<std::string> names;
  for (const auto& [name, number] : kAlgorithms) names.push_back(name);
  OptionTable<MeshOptions> t;
  t.add("size_min", &MeshOptions::size_min, real(0),
        "smallest element size (Mesh.MeshSizeMin; 0 = Gmsh's default)");
  t.add("size_max", &MeshOptions::size_max, real(0),
        "largest element size (Mesh.MeshSizeMax; 0 = Gmsh's default)");
  t.add("factor", &MeshOptions::factor, real(0),
        "factor on all sizes (Mesh.MeshSizeFactor; 0 = the model's, e.g. set by the .geo)");
  t.add("algorithm", &MeshOptions::algorithm, choice(kAlgorithms),
        names_text(names) +
            " (model: the model's Mesh.Algorithm, as its .geo or script set it; "
            "Gmsh's default is frontal)");
  t.add("max_triangles", &MeshOptions::max_triangles, real(1, 1e12),
        "error if Gmsh makes more boundary lines, triangles or tetrahedra than this");
  t.add("max_seconds", &MeshOptions::max_seconds, real(1, 1e7),
        "error if Gmsh's meshing takes longer (wall seconds)");
  t.check([](const MeshOptions& o) {
    return o.size_max > 0 && o.size_min > o.size_max ? "need size_min <= size_max (0 = unset)" : "";
  });
  return make_stage<MeshOptions>(
      "mesh",
      "new linear mesh of the input's CAD by Gmsh (replaces any mesh): triangles, or tetrahedra "
      "if it has volumes",
      t, run, true, true, true);
}

}  // namespace homesh
