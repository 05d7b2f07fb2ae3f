// homesh command line: homesh INPUT [-m STAGE[:key=value...]]... [OUTPUT.msh | OUTPUT.vtu]
#include <fmt/core.h>
#include <gmsh.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>

#include "core/allocator_tuning.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "fem/cholmod_memory.h"
#include "fem/petsc_solver.h"
#include "pipeline/output_format.h"
#include "pipeline/run_pipeline.h"
#include "pipeline/stage_registry.h"
#include "quality/measure_registry.h"

namespace {

extern "C" void on_signal(int sig) {
  homesh::AtomicFile::remove_pending();
  _exit(128 + sig);
}

std::string stage_list() {
  std::string out = "stages (homesh --help STAGE for options):\n";
  for (const auto& s : homesh::stages()) out += fmt::format("  {:<10}{}\n", s.name, s.summary);
  return out;
}

std::string quoted_command_line(int argc, char** argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool plain = arg.find_first_of(" \t\"'\\$") == std::string::npos && !arg.empty();
    line += (i ? " " : "") + (plain ? arg : "'" + arg + "'");
  }
  return line;
}

int run(int argc, char** argv, const homesh::ParallelSession& parallel) {
  CLI::App app{"homesh: curved, valid high-order triangle meshes for Gmsh users", "homesh"};
  app.set_help_flag();
  std::string input, output;
  std::vector<std::string> modules;
  std::string help_stage;
  std::vector<std::pair<std::string, std::string>> set_numbers, set_strings;
  bool list = false, list_measures = false, quiet = false, verbose = false, keep_invalid = false,
       trust_geo = false, version = false;
  app.add_option("INPUT", input, "the geometry or mesh: .geo .step .stp .brep .iges .igs .msh");
  std::string formats = "the file to write, by its extension (none: nothing is written):";
  for (const auto& f : homesh::output_formats())
    formats += "\n  ." + f.extension + ": " + f.summary;
  app.add_option("OUTPUT", output, formats);
  app.add_option("-m,--module", modules, "stage to run, as name:key=value:... (repeatable)")
      ->allow_extra_args(false);
  auto* help =
      app.add_option("-h,--help", help_stage, "this help, or a stage's options")->expected(0, 1);
  app.add_flag("--list", list, "list the stages");
  app.add_flag("--measures", list_measures, "list the quality measures");
  app.add_flag("--keep-invalid", keep_invalid,
               "write the output even if some element is not certified valid");
  app.add_flag("--trust-geo", trust_geo,
               "let a .geo input run commands that reach outside the model (System, "
               "SystemCall, Save, ...); refused otherwise");
  app.add_option("--setnumber", set_numbers,
                 "set a .geo parameter (DefineConstant) before reading, as Gmsh's -setnumber")
      ->allow_extra_args(false)
      ->type_name("NAME VALUE");
  app.add_option("--setstring", set_strings,
                 "set a .geo string parameter before reading, as Gmsh's -setstring")
      ->allow_extra_args(false)
      ->type_name("NAME VALUE");
  app.add_flag("--version", version, "print homesh's and Gmsh's versions");
  app.add_flag("-q,--quiet", quiet, "print warnings and errors only");
  app.add_flag("-v,--verbose", verbose, "show Gmsh's own messages");
  app.footer("example: homesh geo/naca.geo -m mesh -m order:p=4 -m info out.msh");
  // Gmsh spells its long options with one dash (-setnumber): so may homesh's users.
  std::vector<std::string> args;
  for (int i = argc - 1; i > 0; --i) {
    const std::string a = argv[i];
    args.push_back(a == "-setnumber" || a == "-setstring" ? "-" + a : a);
  }
  app.parse(args);

  if (help->count() > 0) {
    if (help_stage.empty())
      std::fputs((app.help() + "\n" + stage_list()).c_str(), stdout);
    else
      std::fputs(homesh::stage_help(homesh::stage(help_stage)).c_str(), stdout);
    return 0;
  }
  if (version) {
    gmsh::initialize(0, nullptr, false);
    std::string gmsh_version;
    gmsh::option::getString("General.Version", gmsh_version);
    gmsh::finalize();
    std::fputs(("homesh " HOMESH_VERSION " (Gmsh " + gmsh_version + ")\n").c_str(), stdout);
    return 0;
  }
  if (list) {
    std::fputs(stage_list().c_str(), stdout);
    return 0;
  }
  if (list_measures) {
    for (const auto& q : homesh::measures())
      std::fputs(
          fmt::format("  {:<4} {:<28} {}   [{}]\n", q.name, q.title, q.formula, q.source).c_str(),
          stdout);
    return 0;
  }
  if (input.empty()) throw CLI::RequiredError("INPUT");

  std::vector<homesh::StageCall> calls;
  for (const auto& m : modules) calls.push_back(homesh::parse_stage_call(m));
  // Every stage's options are checked before the input is read (run_stages
  // reads them again into the plan): a typo costs no time on a large input.
  for (const auto& c : calls) homesh::stage(c.name).parse(c.given);
  // The output is checked before any work: a bad path costs no minutes of meshing.
  if (!output.empty()) homesh::check_output_path(output);

  // Gmsh reads -setnumber/-setstring from its own command line, before any file.
  std::vector<std::string> gmsh_args = {"homesh"};
  for (const auto& [name, value] : set_numbers)
    gmsh_args.insert(gmsh_args.end(), {"-setnumber", name, value});
  for (const auto& [name, value] : set_strings)
    gmsh_args.insert(gmsh_args.end(), {"-setstring", name, value});
  std::vector<char*> gmsh_argv;
  for (auto& a : gmsh_args) gmsh_argv.push_back(a.data());
  gmsh::initialize(static_cast<int>(gmsh_argv.size()), gmsh_argv.data(), false);
  gmsh::option::setNumber("General.Terminal", verbose ? 1 : 0);
  // Gmsh errors are logged and turned into homesh's errors (gmsh/gmsh_call.h),
  // never thrown from inside Gmsh's OpenMP regions, where they would abort.
  gmsh::option::setNumber("General.AbortOnError", 0);
  homesh::Context ctx;
  // Under mpirun every rank runs the pipeline on the whole mesh (only the
  // petsc solve is shared: fem/petsc_solver.h); rank 0 alone reports and writes.
  ctx.log.quiet = quiet || !parallel.root();
  ctx.keep_invalid = keep_invalid;
  ctx.trust_geo = trust_geo;
  if (output.empty())
    ctx.log.info("no OUTPUT given: the result will not be written (homesh {} ... {})", input,
                 homesh::output_formats_usage());
  homesh::load_input(input, ctx);
  homesh::run_stages(calls, ctx);
  if (!output.empty() && parallel.root())
    homesh::write_output(output, "homesh " HOMESH_VERSION "\n" + quoted_command_line(argc, argv),
                         ctx);
  gmsh::finalize();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  homesh::tune_allocator();          // core/allocator_tuning.h says why
  homesh::route_cholmod_memory();    // fem/cholmod_memory.h says why
  homesh::ParallelSession parallel;  // under mpirun: PETSc and MPI
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  // Past a file-size limit, writes fail with EFBIG and homesh says so, instead
  // of the process being killed with its output half-written.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    return run(argc, argv, parallel);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return 0;
    std::fprintf(stderr, "homesh: error: %s (see homesh --help)\n", e.what());
    return 2;
  } catch (const homesh::Error& e) {
    std::fprintf(stderr, "homesh: error: %s\n", e.what());
  } catch (const std::string& e) {
    std::fprintf(stderr, "homesh: error: Gmsh: %s\n", e.c_str());
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr,
                 "homesh: error: out of memory (the input or an option asks for more "
                 "than this machine has)\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "homesh: error: %s\n", e.what());
  }
  return 1;
}
