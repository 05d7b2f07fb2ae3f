// `import homesh`: the pipeline stages as Python functions acting on the
// current Gmsh model of the same process (the Python gmsh module and this
// extension share one libgmsh). homesh never initializes or finalizes Gmsh.
//
//   gmsh.initialize(); gmsh.open("geo/naca.geo"); gmsh.model.mesh.generate(2)
//   homesh.order(p=4)          # any stage, options as keyword arguments
//   homesh.write("out.msh")    # mesh + views + .opt sidecar, atomically
#include <gmsh.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "core/error.h"
#include "gmsh/gmsh_call.h"
#include "gmsh/read_model.h"
#include "gmsh/views.h"
#include "gmsh/write_model.h"
#include "gmsh/write_msh.h"
#include "pipeline/stage_registry.h"

namespace py = pybind11;

namespace homesh {
namespace {

bool quiet = false;

std::string option_text(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::string joined;
    for (const auto& item : value) joined += (joined.empty() ? "" : ",") + option_text(item);
    return joined;
  }
  return py::str(value).cast<std::string>();
}

/// Runs one stage on the current model and writes the result back into it.
py::dict run_stage(const std::string& name, const py::kwargs& kwargs) {
  const Stage& s = stage(name);
  std::map<std::string, std::string> given;
  for (const auto& [key, value] : kwargs) given[key.cast<std::string>()] = option_text(value);
  const Options options(s.name, s.options, given);

  Context ctx;
  ctx.input = "the current Gmsh model";
  ctx.log.quiet = quiet;
  ctx.has_cad = gmsh_adapter::model_has_cad();
  if (gmsh_adapter::model_has_mesh()) ctx.mesh = gmsh_adapter::read_model(ctx.input);
  s.run(ctx, options);

  py::dict result;
  result["results"] = ctx.results;
  if (!ctx.mesh) return result;
  std::vector<int> views;
  gmsh_adapter::gmsh_call("writing the mesh into the current Gmsh model", [&] {
    views = gmsh_adapter::add_views(ctx.fields, gmsh_adapter::write_model(*ctx.mesh));
  });
  result["order"] = ctx.mesh->order;
  result["nodes"] = ctx.mesh->num_nodes();
  result["triangles"] = ctx.mesh->num_triangles();
  result["views"] = views;
  return result;
}

void write_file(const std::string& path) {
  std::vector<int> views;
  gmsh::view::getTags(views);
  const auto argv = py::module_::import("sys").attr("argv").cast<std::vector<std::string>>();
  std::string line = "python3";
  for (const auto& a : argv) line += " " + a;
  gmsh_adapter::write_msh(path, views, "homesh (Python)\n" + line);
}

}  // namespace
}  // namespace homesh

PYBIND11_MODULE(homesh, m) {
  using namespace homesh;
  m.doc() = "homesh: curved, valid high-order triangle meshes on the current Gmsh model";
  static py::exception<Error> error(m, "Error");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      PyErr_SetString(error.ptr(), e.what());
    } catch (const std::string& e) {
      PyErr_SetString(error.ptr(), ("Gmsh: " + e).c_str());
    }
  });

  m.def("run", &run_stage, py::arg("stage"),
        "Run a stage (see stages()) on the current Gmsh model, options as keyword arguments; "
        "returns order, node and triangle counts, the tags of the views it added and the numbers "
        "the stage reports (results).");
  m.def("write", &write_file, py::arg("path"),
        "Write the current model's mesh and views to a MSH 4.1 file (atomically) with its .opt "
        "sidecar.");
  m.def("set_quiet", [](bool q) { quiet = q; }, py::arg("quiet") = true,
        "Silence homesh's progress messages.");
  m.def("stages", [] {
    py::list out;
    for (const Stage& s : stages()) {
      py::dict options;
      for (const auto& o : s.options) options[o.name.c_str()] = py::make_tuple(o.default_value, o.help);
      out.append(py::dict(py::arg("name") = s.name, py::arg("summary") = s.summary,
                          py::arg("options") = options));
    }
    return out;
  });
  // One function per stage, named after it, so `homesh.order(p=4)` reads like the CLI.
  for (const Stage& s : stages()) {
    std::string doc = stage_help(s);
    const std::string name = s.name;
    m.def(name.c_str(), [name](const py::kwargs& kw) { return run_stage(name, kw); },
          doc.c_str());
  }
}
