#pragma once
// homesh for C++ Gmsh-API programs: the pipeline stages as functions acting on
// the current Gmsh model of the same process, as `import homesh` does in
// Python. homesh never initializes or finalizes Gmsh; the program does.
// Installed as <homesh/homesh.h>; it needs only the standard library (link
// the CMake target homesh::homesh, see scripts/examples/cpp/).
//
//   gmsh::initialize();
//   gmsh::open("plate.geo");
//   gmsh::model::mesh::generate(2);
//   homesh::api::curve({{"p", "3"}});               // order 3, curved, valid
//   auto q = homesh::api::quality({{"measures", "Q4"}});
//   std::cout << q.validity.line << "\n";           // "validity: 0 invalid of ..."
//   homesh::api::write("plate.msh");                // mesh, views, .opt sidecar
//
// Options are the CLI stage options (`homesh --help STAGE`), values written
// as on the command line ({"nu", "0.45"}, {"measures", "Q4,Q17"}), all read
// and checked before the stage starts. Every
// failure throws homesh::Error with the CLI's message (Gmsh's own errors as
// "Gmsh: ...").
#include <functional>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "core/error.h"

namespace homesh::api {

/// Options of one stage: option name -> value as on the command line.
using StageOptions = std::map<std::string, std::string>;

/// A number a stage reports: a count (int), a flag (bool) or a measurement (double).
using ResultValue = std::variant<bool, int, double>;

/// Certified validity of the model's mesh (Bezier bounds of the Jacobian
/// determinant; quality/mesh_validity.h).
struct Validity {
  int triangles = 0;
  int quadrilaterals = 0;
  int tetrahedra = 0;  ///< of a volume mesh (issue 24): then invalid and worst are over them
  int invalid = 0;     ///< 2D elements (triangles and quadrilaterals) not certified valid
  double worst = 1;    ///< smallest certified minJ/maxJ, in [-1, 1]
  int worst_triangle =
      0;             ///< the Gmsh element tag of the element of `worst` (a quad, a tetrahedron)
  std::string line;  ///< the CLI's one-line summary ("validity: ...")
};

/// What a stage did to the current model.
struct Result {
  /// Named numbers the stage reports (e.g. rotate's theta_max, quality's
  /// invalid and Q4_min); empty for stages that report none. Validity's
  /// names are the names throughout: quality reports triangles, invalid,
  /// worst and worst_triangle; rotate the worst minJ/maxJ of its steps as worst.
  std::map<std::string, ResultValue> results;
  bool has_mesh = false;  ///< the model holds a mesh after the stage
  int order = 0;          ///< element order of that mesh
  int nodes = 0;
  int triangles = 0;
  int quadrilaterals = 0;
  int tetrahedra = 0;      ///< of a volume mesh (its triangles are those of its surfaces)
  std::vector<int> views;  ///< tags of the Gmsh views the stage added
  Validity validity;       ///< of the mesh after the stage (if has_mesh)
};

/// One option of a stage, with its default and help text.
struct OptionInfo {
  std::string name;
  std::string default_value;
  std::string help;
};

/// A stage of the registry: name, one-line summary, options.
struct StageInfo {
  std::string name;
  std::string summary;
  std::vector<OptionInfo> options;
  std::string help;  ///< the text of `homesh --help NAME`
};

/// Every stage, in the order `homesh --list` shows them.
std::vector<StageInfo> stages();

/// Runs stage `name` on the current Gmsh model: reads its mesh (if any),
/// transforms it, and writes the mesh and the stage's fields (as views) back
/// into the model. The views are styled as a user who opens the written file
/// sees them (the certified minJ/maxJ shown on [0, 1], drawn curved, the other
/// views hidden; high-order edges drawn curved), so gmsh::fltk::run() after
/// homesh shows the same.
Result run(const std::string& name, const StageOptions& options = {});

/// One function per stage, named after it: run("mesh", options) etc.
Result mesh(const StageOptions& options = {});
Result order(const StageOptions& options = {});
Result layers(const StageOptions& options = {});
Result curve(const StageOptions& options = {});
Result optimise(const StageOptions& options = {});
Result rotate(const StageOptions& options = {});
Result quality(const StageOptions& options = {});
Result info(const StageOptions& options = {});
Result voronoi(const StageOptions& options = {});

/// Certified validity of the current model's mesh.
Validity validity();

/// Certifies the current model's mesh, then writes it and all its views to
/// `path`, atomically, every write checked, in the format its extension names:
/// a `.msh` (in the MSH version and encoding set in Gmsh's options) with the
/// `.opt` sidecar that displays curved fields curved, or a `.vtu` (VTK XML,
/// Lagrange cells of the mesh's order, the views as cell and point data and
/// the certified minJ/maxJ always among them, for ParaView). `provenance`
/// (e.g. the program's command line) and the validity line are recorded in
/// the file. Throws homesh::Error and writes nothing if a triangle is not
/// certified valid, unless `keep_invalid`, or if `path` has another extension.
void write(const std::string& path, const std::string& provenance = "homesh C++ API",
           bool keep_invalid = false);

/// Silences the stages' reports on stdout (warnings stay) and progress.
/// Gmsh's General.Verbosity is followed as well: below 4 no reports, below 2
/// no warnings either.
void set_quiet(bool quiet = true);

/// Where the stages' messages go: `level` 0 for reports, 1 for warnings. An
/// empty sink (the default) prints reports on stdout and warnings on stderr.
using LogSink = std::function<void(int level, const std::string& text)>;
void set_log_sink(LogSink sink);

}  // namespace homesh::api
