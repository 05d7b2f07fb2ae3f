// Progress of a long run: drawn on stderr (one line, redrawn with \r, erased
// at the end) when asked by HOMESH_PROGRESS=1 or when stderr is a terminal;
// nothing at all when stderr is a file or a pipe.
#include <catch2/catch.hpp>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "../support/run_command.h"
#include "../support/temp_dir.h"

namespace {

struct Run {
  int exit_code;
  std::string out;  ///< stdout
  std::string err;  ///< stderr
};

// homesh on geo/GEO with ARGS, stdout and stderr apart.
Run run_apart(const std::string& env, const std::string& geo, const std::string& args) {
  const homesh::test::TempDir dir;
  const std::string err_file = dir / "homesh.err";
  const auto r =
      homesh::test::run_command("(" + env + " " + HOMESH_BINARY + " " + HOMESH_SOURCE_DIR +
                                "/geo/" + geo + " " + args + " 2>" + err_file + ")");
  std::ifstream in(err_file);
  std::stringstream err;
  err << in.rdbuf();
  return {r.exit_code, r.output, err.str()};
}

// The rotation benchmark of geo/README.md (98 degrees).
Run rotate_plate(const std::string& env) {
  return run_apart(env, "plate_hole_fig413.geo", "-m mesh -m curve:p=2:rings=0 -m rotate:nu=0.45");
}

}  // namespace

TEST_CASE("progress: HOMESH_PROGRESS=1 draws the rotation's steps under its stage", "[app]") {
  const Run r = rotate_plate("HOMESH_PROGRESS=1");
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("rotate: theta_max = 98 deg") != std::string::npos);
  // The curve stage's increments come first, erased before it reports.
  const std::regex curve(
      R"(\rhomesh: stage 2/3 curve \| boundary motion \d+ % done, solve \d+\x1b\[K)");
  REQUIRE(r.err.rfind("\rhomesh: stage 2/3 curve | boundary motion 0 % done, solve 1", 0) == 0);
  const auto rotating = r.err.find("\rhomesh: stage 3/3 rotate");
  REQUIRE(rotating != std::string::npos);
  REQUIRE(std::regex_replace(r.err.substr(0, rotating), curve, "") == "\r\033[K");
  // The first step is drawn at once; later ones at most every 0.1 s, in order, up to 98.
  REQUIRE(r.err.find("\rhomesh: stage 3/3 rotate | step 1/360 1 deg\033[K") == rotating);
  const std::regex step(R"(\rhomesh: stage 3/3 rotate \| step (\d+)/360 (\d+) deg\x1b\[K)");
  int draws = 0, last = 0;
  for (auto it = std::sregex_iterator(r.err.begin(), r.err.end(), step);
       it != std::sregex_iterator(); ++it, ++draws) {
    const int k = std::stoi((*it)[1]);
    REQUIRE(k > last);
    REQUIRE(k <= 98);
    REQUIRE(std::stoi((*it)[2]) == k);
    last = k;
  }
  REQUIRE(draws >= 1);
  // The line is erased before the stage reports, so nothing else is on stderr.
  const std::string erased = std::regex_replace(r.err.substr(rotating), step, "");
  REQUIRE(erased == "\r\033[K");
  // No progress line on stdout.
  REQUIRE(r.out.find("step 1/360") == std::string::npos);
}

TEST_CASE("progress: stderr not a terminal, or HOMESH_PROGRESS=0: not a byte", "[app]") {
  for (const std::string env : {"env -u HOMESH_PROGRESS", "HOMESH_PROGRESS=0"}) {
    CAPTURE(env);
    const Run r = rotate_plate(env);
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    REQUIRE(r.out.find("rotate: theta_max = 98 deg") != std::string::npos);
    REQUIRE(r.err.empty());
  }
}

TEST_CASE("progress: crystal growth shows its phases and Lloyd's iterations", "[app]") {
  const Run r = run_apart("HOMESH_PROGRESS=1", "plate_hole.geo", "-m voronoi:lloyd=2");
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.err.rfind("\rhomesh: stage 1/1 voronoi | phase 0/3 Lloyd's iteration on the seeds",
                      0) == 0);
  REQUIRE(r.err.find("| iteration 1/2") != std::string::npos);
  // Later phases are drawn only if 0.1 s have passed (not on this small case);
  // the line is erased at the end.
  REQUIRE(r.err.size() >= 4);
  REQUIRE(r.err.substr(r.err.size() - 4) == "\r\033[K");
  REQUIRE(run_apart("HOMESH_PROGRESS=0", "plate_hole.geo", "-m voronoi:lloyd=2").err.empty());
}

TEST_CASE("progress: curving shows the share of the boundary motion reached", "[app]") {
  const Run r =
      run_apart("HOMESH_PROGRESS=1", "plate_hole.geo",
                "-m mesh -m curve:p=3:increments=4:placed=2");  // placed > 1: always solve
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.err.rfind("\rhomesh: stage 2/2 curve | boundary motion 0 % done, solve 1\033[K", 0) ==
          0);
  REQUIRE(r.err.size() >= 4);
  REQUIRE(r.err.substr(r.err.size() - 4) == "\r\033[K");
}

TEST_CASE("progress: the layers stage shows the room's clearing and push", "[app]") {
  const Run r = run_apart("HOMESH_PROGRESS=1", "naca.geo",
                          "-m mesh -m layers:walls=aerofoil:n=15:first=1e-3:ratio=1.2");
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.err.rfind("\rhomesh: stage 2/2 layers | clearing room 0 nodes removed\033[K", 0) == 0);
  CHECK(r.err.find("| room 0/100 % pushed, step 1") != std::string::npos);
  REQUIRE(r.err.substr(r.err.size() - 4) == "\r\033[K");
}
