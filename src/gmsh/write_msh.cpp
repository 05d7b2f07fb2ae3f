#include "gmsh/write_msh.h"

#include <gmsh.h>

#include <fstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "gmsh/gmsh_call.h"

namespace homesh::gmsh_adapter {

std::string sidecar_options(int num_views) {
  std::string s =
      "// homesh display settings, merged by Gmsh when it opens the .msh beside this file.\n"
      "Mesh.NumSubEdges = 8;  // draw high-order edges curved\n";
  for (int i = 0; i < num_views; ++i) {
    const std::string v = "View[" + std::to_string(i) + "].";
    s += v + "AdaptVisualizationGrid = 1;  // refine curved fields for display\n";
    s += v + "MaxRecursionLevel = 3;\n";
    s += v + "TargetError = 1e-3;\n";
  }
  return s;
}

void write_msh(const std::string& path, const std::vector<int>& view_tags,
               const std::string& provenance) {
  AtomicFile msh(path);
  AtomicFile opt(path + ".opt");
  gmsh_call("cannot write '" + path + "'", [&] {
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.Binary", 0);
    gmsh::option::setNumber("Mesh.SaveAll", 1);
    gmsh::write(msh.temp_path());
    gmsh::option::setNumber("PostProcessing.SaveMesh", 0);
    for (int v : view_tags) gmsh::view::write(v, msh.temp_path(), true);
  });
  {
    std::ofstream out(msh.temp_path(), std::ios::app);
    out << "$HomeshProvenance\n" << provenance << "\n$EndHomeshProvenance\n";
    if (!out) throw Error("cannot write '" + path + "'");
  }
  {
    std::ofstream out(opt.temp_path());
    out << sidecar_options(static_cast<int>(view_tags.size()));
    if (!out) throw Error("cannot write '" + path + ".opt'");
  }
  msh.commit();
  opt.commit();
}

}  // namespace homesh::gmsh_adapter
