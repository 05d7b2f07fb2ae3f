// homesh command line: homesh INPUT [-m STAGE[:key=value...]]... [OUTPUT]
#include <gmsh.h>

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <csignal>
#include <cstdio>
#include <unistd.h>

#include "core/atomic_file.h"
#include "core/error.h"
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

int run(int argc, char** argv) {
  CLI::App app{"homesh: curved, valid high-order triangle meshes for Gmsh users", "homesh"};
  app.set_help_flag();
  std::vector<std::string> files, modules;
  std::string help_stage;
  bool list = false, list_measures = false, quiet = false, verbose = false, keep_invalid = false;
  app.add_option("files", files, "INPUT (.geo .step .brep .msh) and optional OUTPUT (.msh)")
      ->expected(0, 2);
  app.add_option("-m,--module", modules, "stage to run, as name:key=value:... (repeatable)")
      ->allow_extra_args(false);
  auto* help = app.add_option("-h,--help", help_stage, "this help, or a stage's options")
                   ->expected(0, 1);
  app.add_flag("--list", list, "list the stages");
  app.add_flag("--measures", list_measures, "list the quality measures");
  app.add_flag("--keep-invalid", keep_invalid,
               "write the output even if some element is not certified valid");
  app.add_flag("-q,--quiet", quiet, "print warnings and errors only");
  app.add_flag("-v,--verbose", verbose, "show Gmsh's own messages");
  app.footer("example: homesh geo/naca.geo -m mesh -m order:p=4 -m info out.msh");
  app.parse(argc, argv);

  if (help->count() > 0) {
    if (help_stage.empty())
      std::fputs((app.help() + "\n" + stage_list()).c_str(), stdout);
    else
      std::fputs(homesh::stage_help(homesh::stage(help_stage)).c_str(), stdout);
    return 0;
  }
  if (list) {
    std::fputs(stage_list().c_str(), stdout);
    return 0;
  }
  if (list_measures) {
    for (const auto& q : homesh::measures())
      std::fputs(fmt::format("  {:<4} {:<28} {}   [{}]\n", q.name, q.title, q.formula, q.source).c_str(),
                 stdout);
    return 0;
  }
  if (files.empty()) throw CLI::RequiredError("INPUT");

  std::vector<homesh::StageCall> calls;
  for (const auto& m : modules) calls.push_back(homesh::parse_stage_call(m));

  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", verbose ? 1 : 0);
  homesh::Context ctx;
  ctx.log.quiet = quiet;
  ctx.keep_invalid = keep_invalid;
  homesh::load_input(files[0], ctx);
  homesh::run_stages(calls, ctx);
  if (files.size() > 1)
    homesh::write_output(files[1], "homesh " HOMESH_VERSION "\n" + quoted_command_line(argc, argv),
                         ctx);
  gmsh::finalize();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    return run(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return 0;
    std::fprintf(stderr, "homesh: error: %s (see homesh --help)\n", e.what());
    return 2;
  } catch (const homesh::Error& e) {
    std::fprintf(stderr, "homesh: error: %s\n", e.what());
  } catch (const std::string& e) {
    std::fprintf(stderr, "homesh: error: Gmsh: %s\n", e.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "homesh: error: %s\n", e.what());
  }
  return 1;
}
