#include "pipeline/stages/mesh_stage.h"

#include <gmsh.h>

#include <map>

#include "core/error.h"
#include "gmsh/gmsh_call.h"
#include "gmsh/read_model.h"

namespace homesh {
namespace {

// Gmsh's 2D algorithms that make triangles (Mesh.Algorithm numbers).
const std::map<std::string, int>& algorithms() {
  static const std::map<std::string, int> table = {
      {"meshadapt", 1}, {"auto", 2}, {"delaunay", 5}, {"frontal", 6}, {"bamg", 7}};
  return table;
}

void run(Context& ctx, const Options& opt) {
  ctx.require_cad("mesh");
  const std::string algorithm = opt.get_string("algorithm");
  const auto it = algorithms().find(algorithm);
  if (it == algorithms().end())
    throw Error("stage 'mesh': option algorithm=" + algorithm +
                ": unknown (meshadapt, auto, delaunay, frontal, bamg)");
  const double size_min = opt.get_double("size_min");
  const double size_max = opt.get_double("size_max");
  const double factor = opt.get_double("factor");
  if (size_min < 0 || size_max < 0 || factor <= 0 || (size_max > 0 && size_min > size_max))
    throw Error("stage 'mesh': need 0 <= size_min <= size_max (0 = unset) and factor > 0");

  gmsh_adapter::gmsh_call("stage 'mesh' on " + ctx.input, [&] {
    gmsh::option::setNumber("Mesh.Algorithm", it->second);
    if (size_min > 0) gmsh::option::setNumber("Mesh.MeshSizeMin", size_min);
    if (size_max > 0) gmsh::option::setNumber("Mesh.MeshSizeMax", size_max);
    gmsh::option::setNumber("Mesh.MeshSizeFactor", factor);
    gmsh::option::setNumber("Mesh.ElementOrder", 1);
    gmsh::option::setNumber("Mesh.RecombineAll", 0);
    gmsh::model::mesh::clear();
    gmsh::model::mesh::generate(2);
  });
  ctx.mesh = gmsh_adapter::read_model(ctx.input);
  ctx.fields.clear();
  ctx.log.info("mesh: {} nodes, {} triangles, {} boundary lines", ctx.mesh->num_nodes(),
               ctx.mesh->num_triangles(), ctx.mesh->num_lines());
}

}  // namespace

Stage mesh_stage() {
  return {"mesh",
          "new linear triangle mesh of the input's CAD by Gmsh (replaces any mesh)",
          {{"size_min", "0", "smallest element size (Mesh.MeshSizeMin; 0 = Gmsh's default)"},
           {"size_max", "0", "largest element size (Mesh.MeshSizeMax; 0 = Gmsh's default)"},
           {"factor", "1", "factor on all sizes (Mesh.MeshSizeFactor)"},
           {"algorithm", "frontal", "meshadapt | auto | delaunay | frontal | bamg"}},
          run, true};
}

}  // namespace homesh
