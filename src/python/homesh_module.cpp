// `import homesh`: the pipeline stages as Python functions acting on the
// current Gmsh model of the same process (the Python gmsh module and this
// extension share one libgmsh), through the C++ API (api/homesh.h): the same
// functions, errors and results. homesh never initializes or finalizes Gmsh.
//
//   gmsh.initialize(); gmsh.open("geo/naca.geo"); gmsh.model.mesh.generate(2)
//   homesh.order(p=4)          # any stage, options as keyword arguments
//   homesh.write("out.msh")    # mesh + views + .opt sidecar, atomically (or "out.vtu")
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "api/homesh.h"
#include "core/allocator_tuning.h"
#include "fem/cholmod_memory.h"

namespace py = pybind11;

namespace homesh {
namespace {

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

py::dict validity_dict(const api::Validity& v) {
  // worst_element: the worst 2D element's Gmsh tag (a triangle or a quadrilateral);
  // worst_triangle, its older name, stays for scripts written before quadrilaterals.
  return py::dict(py::arg("triangles") = v.triangles, py::arg("quadrilaterals") = v.quadrilaterals,
                  py::arg("tetrahedra") = v.tetrahedra, py::arg("invalid") = v.invalid,
                  py::arg("worst") = v.worst, py::arg("worst_element") = v.worst_triangle,
                  py::arg("worst_triangle") = v.worst_triangle, py::arg("line") = v.line);
}

/// Runs one stage on the current model (api::run) and returns its result as a dict.
py::dict run_stage(const std::string& name, const py::kwargs& kwargs) {
  api::StageOptions given;
  for (const auto& [key, value] : kwargs) given[key.cast<std::string>()] = option_text(value);
  const api::Result r = api::run(name, given);
  py::dict result;
  result["results"] = r.results;
  if (!r.has_mesh) return result;
  result["order"] = r.order;
  result["nodes"] = r.nodes;
  result["triangles"] = r.triangles;
  result["quadrilaterals"] = r.quadrilaterals;
  result["tetrahedra"] = r.tetrahedra;
  result["views"] = r.views;
  result["validity"] = validity_dict(r.validity);
  return result;
}

void write_file(const std::string& path, bool keep_invalid) {
  const auto argv = py::module_::import("sys").attr("argv").cast<std::vector<std::string>>();
  std::string line = "python3";
  for (const auto& a : argv) line += " " + a;
  api::write(path, "homesh (Python)\n" + line, keep_invalid);
}

}  // namespace
}  // namespace homesh

PYBIND11_MODULE(homesh, m) {
  using namespace homesh;
  m.doc() = "homesh: curved, valid high-order triangle meshes on the current Gmsh model";
  tune_allocator();        // core/allocator_tuning.h says why (HOMESH_MALLOC=default: not)
  route_cholmod_memory();  // fem/cholmod_memory.h says why
  static py::exception<Error> error(m, "Error");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      PyErr_SetString(error.ptr(), e.what());
    }
  });

  // homesh's messages reach Python: the "homesh" logger where logging is set
  // up (a handler on it or an ancestor), else sys.stdout / sys.stderr, so that
  // contextlib.redirect_stdout and notebooks capture them.
  api::set_log_sink([](int level, const std::string& text) {
    py::gil_scoped_acquire gil;
    const py::object logger = py::module_::import("logging").attr("getLogger")("homesh");
    if (logger.attr("hasHandlers")().cast<bool>()) {
      logger.attr("log")(level == 0 ? 20 : 30, text);  // logging.INFO, logging.WARNING
    } else {
      const py::object sys = py::module_::import("sys");
      const py::object stream = sys.attr(level == 0 ? "stdout" : "stderr");
      stream.attr("write")((level == 0 ? "" : "homesh: warning: ") + text + "\n");
    }
  });
  m.def("run", &run_stage, py::arg("stage"),
        "Run a stage (see stages()) on the current Gmsh model, options as keyword arguments "
        "(checked before the stage starts); returns order, node and triangle counts, the tags "
        "of the views it added, the numbers the stage reports (results: counts as int, flags "
        "as bool, measurements as float) and the mesh's certified validity (see validity(), "
        "whose key names quality's results share). The views are styled as opening the "
        "written file shows them (certified minJ/maxJ shown on [0, 1], drawn curved, the others "
        "hidden): gmsh.fltk.run() afterwards shows the same.");
  m.def("write", &write_file, py::arg("path"), py::arg("keep_invalid") = false,
        "Certify the current model's mesh, then write it and its views atomically to a .msh file "
        "(the MSH version and encoding of Gmsh's options) with its .opt sidecar, which styles "
        "the views as they are in this process, or to a .vtu file (VTK XML with Lagrange cells, "
        "the views and the certified minJ/maxJ as cell and point data, for ParaView), as the "
        "path's extension says; refuses a mesh not certified valid unless keep_invalid.");
  m.def("set_quiet", &api::set_quiet, py::arg("quiet") = true,
        "Silence homesh's reports and progress (warnings stay).");
  m.def(
      "validity", [] { return validity_dict(api::validity()); },
      "Certified validity of the current model's mesh: triangles, invalid, worst minJ/maxJ, "
      "its triangle (1-based) and the CLI's validity line.");
  m.def(
      "stages",
      [] {
        py::list out;
        for (const api::StageInfo& s : api::stages()) {
          py::dict options;
          for (const auto& o : s.options)
            options[o.name.c_str()] = py::make_tuple(o.default_value, o.help);
          out.append(py::dict(py::arg("name") = s.name, py::arg("summary") = s.summary,
                              py::arg("options") = options));
        }
        return out;
      },
      "Every stage, in the order of homesh --list: name, summary and options {name: (default, "
      "help)}, the defaults those of the library's options structs (homesh --help STAGE).");
  // One function per stage, named after it, so `homesh.order(p=4)` reads like the CLI.
  for (const api::StageInfo& s : api::stages()) {
    const std::string name = s.name;
    m.def(
        name.c_str(), [name](const py::kwargs& kw) { return run_stage(name, kw); }, s.help.c_str());
  }
}
