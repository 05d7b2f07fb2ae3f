// The voronoi stage run as a user does: a mesh of the CAD dual to the crystal
// Voronoi diagram, valid, conforming, classified, and accepted by the other
// stages.
#include <gmsh.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <regex>
#include <utility>

#include "../support/gmsh_session.h"
#include "../support/run_command.h"
#include "../support/temp_dir.h"
#include "gmsh/read_model.h"

using homesh::test::run_homesh;
using homesh::test::TempDir;

namespace {

using homesh::test::geo;

// The number in the log after `label`, e.g. "... (\d+) triangles".
int logged(const std::string& log, const std::string& pattern) {
  std::smatch m;
  REQUIRE(std::regex_search(log, m, std::regex(pattern)));
  return std::stoi(m[1]);
}

// The worst minJ/maxJ of the output's validity line, which must say 0 invalid.
double certified_worst(const std::string& log) {
  std::smatch m;
  REQUIRE(std::regex_search(
      log, m, std::regex(R"(validity: 0 invalid of \d+ triangles.*worst minJ/maxJ (\d\.\d+))")));
  return std::stod(m[1]);
}

// The minimum and mean of measure `name` in the quality stage's log.
std::pair<double, double> quality(const std::string& log, const std::string& name) {
  std::smatch m;
  REQUIRE(std::regex_search(log, m, std::regex(name + R"( +min ([0-9.]+) +mean ([0-9.]+))")));
  return {std::stod(m[1]), std::stod(m[2])};
}

homesh::Mesh read_output(const std::string& path) {
  homesh::test::GmshSession session;
  gmsh::open(path);
  return homesh::gmsh_adapter::read_model(path);
}

}  // namespace

TEST_CASE("voronoi: the plate with a hole, its dual conforming, then curved to order 3",
          "[app][voronoi]") {
  const TempDir dir;
  const std::string out = dir / "plate.msh";
  const auto r = run_homesh(geo + "plate_hole.geo -m voronoi -m curve:p=3 -m quality " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  // The isotropic metric takes the exact dual: the seeds' Delaunay
  // triangulation holds every boundary segment.
  CHECK(r.output.find("exact dual (Delaunay of the seeds") != std::string::npos);
  CHECK(logged(r.output, R"((\d+) boundary segments not among their edges)") == 0);
  const int triangles = logged(r.output, R"(voronoi: metric iso[^:]*: \d+ nodes, (\d+) triangles)");
  CHECK(logged(r.output, R"((\d+) from the fill)") == 0);
  CHECK(r.output.find("validity: 0 invalid of " + std::to_string(triangles)) != std::string::npos);
  const homesh::Mesh m = read_output(out);
  CHECK(m.order == 3);
  CHECK(m.num_triangles() == triangles);
  // Boundary lines on the hole (r = 0.5) or the square, nodes classified on
  // their curve; every physical group kept.
  int on_hole = 0;
  for (int k = 0; k < m.num_lines(); ++k) {
    const Eigen::Vector2d a = m.x.col(m.line(0, k));
    if (std::abs(a.norm() - 0.5) < 1e-9)
      ++on_hole;
    else
      CHECK(std::abs(a.cwiseAbs().maxCoeff() - 1.0) < 1e-12);
    CHECK(m.node_class[m.line(2, k)].dim == 1);
  }
  CHECK(on_hole > 20);
  CHECK(m.physicals.size() == 3);
  // Gmsh's default mesh has 208 nodes: the metric sizes match it roughly.
  const int nodes = logged(r.output, R"(voronoi: metric iso[^:]*: (\d+) nodes)");
  CHECK(nodes > 150);
  CHECK(nodes < 260);
}

TEST_CASE("voronoi: NACA-7526 on a 600 x 600 grid, the strip the dual misses regrown finer",
          "[app][voronoi]") {
  const TempDir dir;
  const std::string out = dir / "naca.msh";
  const auto r = run_homesh(geo + "naca.geo -m voronoi:grid=700:dual=grown -m curve:p=3 " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  // Gmsh's sizes reach 0.006 at the trailing edge, 1.6 cells here: the log
  // says how many triangles came from the dual and how many were filled.
  const int total = logged(r.output, R"(voronoi: surface \d+: (\d+) triangles)");
  const int dual = logged(r.output, R"((\d+) from the dual)");
  CHECK(dual > 0.95 * total);
  // After the clean-up (which may remove nodes of valence 4).
  const int final_count =
      logged(r.output, R"(voronoi: metric iso[^:]*: \d+ nodes, (\d+) triangles)");
  // The 33 segments the 700-node grid misses grow again on windows at least
  // 4 times finer: none is missed after, and the dual conforms: no triangle
  // is filled. On a 600-node grid (1.4 cells a size at the trailing edge)
  // the regrown dual there crosses the wall, and 12 triangles are filled
  // (0 before the iso metric came from Gmsh's mesh at twice the sizes, whose
  // trailing edge's sizes were 0.005; 6 before Lloyd's iteration took exact
  // cells: measured, docs/voronoi.md).
  CHECK(logged(r.output, R"(the dual missed (\d+) boundary segments: regrown)") == 33);
  CHECK(r.output.find("the dual does not conform") == std::string::npos);
  CHECK(logged(r.output, R"((\d+) from the fill)") == 0);
  CHECK(r.output.find("validity: 0 invalid of " + std::to_string(final_count)) !=
        std::string::npos);
  const homesh::Mesh m = read_output(out);
  CHECK(m.num_triangles() == final_count);
  CHECK(m.physicals.size() == 3);
}

TEST_CASE("voronoi: NACA-7526 on an 800 x 800 grid, wall triple points regrown finer, no fill",
          "[app][voronoi]") {
  // Before the windows were at least 4 times finer than the global grid, 5
  // segments whose triple point lies a fraction of a cell inside the wall
  // stayed missed and 21 triangles were filled; now the dual conforms.
  const auto r =
      run_homesh(geo + "naca.geo -m voronoi:grid=800:dual=grown -m quality:measures=Q11");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(logged(r.output, R"(the dual missed (\d+) boundary segments: regrown)") > 0);
  CHECK(logged(r.output, R"((\d+) from the fill)") == 0);
  CHECK(r.output.find("the dual does not conform") == std::string::npos);
  const auto [min, mean] = quality(r.output, "Q11");
  CHECK(min > 0.75);
  CHECK(mean > 0.95);
}

TEST_CASE("voronoi: a boundary-layer metric stretches the triangles at the walls",
          "[app][voronoi]") {
  const TempDir dir;
  const std::string out = dir / "bl.msh";
  const auto iso = run_homesh(geo + "plate_hole.geo -m voronoi " + out);
  const auto bl = run_homesh(geo + "plate_hole.geo -m voronoi:metric=bl " + out);
  INFO(bl.output);
  REQUIRE(bl.exit_code == 0);
  CHECK(bl.output.find("walls: 1 curves not in a group 'farfield'") != std::string::npos);
  const std::string nodes = R"(voronoi: metric [^\n]*: (\d+) nodes)";
  CHECK(logged(bl.output, nodes) > logged(iso.output, nodes) + 30);
  // Twice the default stretching at the wall, in a layer twice as thick: more
  // nodes again; an aspect below 1 is refused, naming the option.
  const auto bl10 =
      run_homesh(geo + "plate_hole.geo -m voronoi:metric=bl:bl_aspect=10:bl_thickness=6 " + out);
  INFO(bl10.output);
  REQUIRE(bl10.exit_code == 0);
  CHECK(logged(bl10.output, nodes) > logged(bl.output, nodes) + 30);
  const auto bad = run_homesh(geo + "plate_hole.geo -m voronoi:metric=bl:bl_aspect=0.5 " + out);
  CHECK(bad.exit_code != 0);
  CHECK(bad.output.find("bl_aspect") != std::string::npos);
}

TEST_CASE(
    "voronoi: a 100:1 boundary layer from the metric, columns across the walls, no fill, "
    "curved to p = 3 above 0.8",
    "[app][voronoi]") {
  // Issue 22's target: metric=bl at 100:1, every triangle from the dual (the
  // seeds' Delaunay triangulation in the metric), valid after curve:p=3 with
  // worst minJ/maxJ >= 0.8; on the plate's hole and on NACA-7526's
  // wall with its sharp trailing edge (a fan of columns).
  const TempDir dir;
  const std::string out = dir / "bl100.msh";
  for (const std::string model : {"plate_hole.geo", "naca.geo"}) {
    const auto r =
        run_homesh(geo + model + " -m voronoi:metric=bl:bl_aspect=100 -m curve:p=3 " + out);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(logged(r.output, R"((\d+) seeds in \d+ columns across the anisotropic walls)") > 300);
    CHECK(logged(r.output, R"(columns across the anisotropic walls \(up to (\d+) a column)") >= 12);
    CHECK(logged(r.output, R"(, (\d+) with an edge left not Delaunay in it)") == 0);
    CHECK(logged(r.output, R"(from the dual, (\d+) from the fill)") == 0);
    CHECK(certified_worst(r.output) >= 0.8);
  }
}

TEST_CASE("voronoi: a user's metric file of 100:1 round the plate's hole, no fill, p = 3 above 0.8",
          "[app][voronoi]") {
  // Issue 22's target for a user metric: the plate's hole (radius 0.5) with
  // a layer given on a 101 x 101 grid: size 0.05 along the hole, 0.0005
  // across it at the wall (100:1), growing linearly to 0.05 at 0.15 out.
  const TempDir dir;
  const std::string metric = dir / "layer.txt", out = dir / "user100.msh";
  {
    std::ofstream f(metric);
    f.precision(12);
    const int n = 101;
    f << "grid " << n << " " << n << " -1 -1 1 1\n";
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = -1 + 2.0 * i / (n - 1), y = -1 + 2.0 * j / (n - 1);
        const double r = std::hypot(x, y), d = std::max(r - 0.5, 0.0);
        const double ht = 0.05, hn = ht * (0.01 + 0.99 * std::min(1.0, d / 0.15));
        const double nx = r > 0 ? x / r : 1, ny = r > 0 ? y / r : 0;
        const double a = 1 / (hn * hn), b = 1 / (ht * ht);
        f << a * nx * nx + b * ny * ny << " " << (a - b) * nx * ny << " "
          << a * ny * ny + b * nx * nx << "\n";
      }
  }
  const auto r =
      run_homesh(geo + "plate_hole.geo -m voronoi:metric=" + metric + " -m curve:p=3 " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(logged(r.output, R"((\d+) seeds in \d+ columns across the anisotropic walls)") > 300);
  CHECK(logged(r.output, R"(from the dual, (\d+) from the fill)") == 0);
  CHECK(certified_worst(r.output) >= 0.8);
}

TEST_CASE("voronoi: seeds and metric from files, errors naming file and line", "[app][voronoi]") {
  const TempDir dir;
  const std::string out = dir / "files.msh";
  const std::string seeds = dir / "seeds.txt";
  std::ofstream(seeds) << "# interior seeds\n0.75 0.75\n-0.75 0.75\n-0.75 -0.75\n0.75 -0.75\n";
  auto r = run_homesh(geo + "plate_hole.geo -m voronoi:seeds=" + seeds + " " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("78 boundary + 0 front + 4 interior seeds") != std::string::npos);
  std::ofstream(seeds) << "0.75 0.75\n\n0.1 0.1\n";
  r = run_homesh(geo + "plate_hole.geo -m voronoi:seeds=" + seeds + " " + out);
  CHECK(r.exit_code != 0);
  CHECK(r.output.find(seeds + ":3: seed (0.1, 0.1) lies outside the domain") != std::string::npos);
  std::ofstream(seeds) << "0.75 0.75\n0.75 0.75\n";
  r = run_homesh(geo + "plate_hole.geo -m voronoi:seeds=" + seeds + " " + out);
  CHECK(r.output.find(seeds + ":2: seed (0.75, 0.75) coincides with the seed on line 1") !=
        std::string::npos);

  const std::string metric = dir / "metric.txt";
  std::ofstream(metric) << "grid 2 2 -1 -1 1 1\n100 0 100\n100 0 100\n100 0 100\n100 0 100\n";
  r = run_homesh(geo + "plate_hole.geo -m voronoi:metric=" + metric + " " + out);
  REQUIRE(r.exit_code == 0);
  // Size 0.1 everywhere: 80 boundary lines on the square, 32 on the hole.
  CHECK(logged(r.output, R"(voronoi: metric [^\n]*triangles, (\d+) boundary lines)") > 105);
  std::ofstream(metric) << "grid 2 2 -1 -1 1 1\n100 0 100\n100 0 100\n1 2 1\n100 0 100\n";
  r = run_homesh(geo + "plate_hole.geo -m voronoi:metric=" + metric + " " + out);
  CHECK(r.exit_code != 0);
  CHECK(r.output.find(metric + ":4: the tensor is not symmetric positive definite") !=
        std::string::npos);
  r = run_homesh(geo + "plate_hole.geo -m voronoi:engine=crystal " + out);
  CHECK(r.output.find("option engine=crystal: expected level_set or fast_marching") !=
        std::string::npos);
  r = run_homesh(geo + "plate_hole.geo -m voronoi:front=rows " + out);
  CHECK(r.exit_code != 0);
  CHECK(r.output.find("option front=rows: not an integer nor 'all'") != std::string::npos);
}

TEST_CASE(
    "voronoi: front rows, Lloyd's iteration, smoothing and clean-up make triangles better than "
    "Gmsh's",
    "[app][voronoi]") {
  const TempDir dir;
  const std::string out = dir / "lloyd.msh";
  const std::string poisson_only = "voronoi:front=0:interior=poisson";
  const auto poisson = run_homesh(geo + "plate_hole.geo -m " + poisson_only +
                                  ":lloyd=0:smooth=0:cleanup=off -m quality " + out);
  const auto lattice = run_homesh(
      geo + "plate_hole.geo -m voronoi:front=0:lloyd=0:smooth=0:cleanup=off -m quality " + out);
  const auto flipped =
      run_homesh(geo + "plate_hole.geo -m " + poisson_only + ":lloyd=0:smooth=0 -m quality " + out);
  const auto no_front =
      run_homesh(geo + "plate_hole.geo -m " + poisson_only + " -m quality " + out);
  const auto front = run_homesh(geo + "plate_hole.geo -m voronoi -m quality " + out);
  const auto gmsh = run_homesh(geo + "plate_hole.geo -m mesh -m quality " + out);
  INFO(poisson.output << lattice.output << flipped.output << no_front.output << front.output
                      << gmsh.output);
  REQUIRE(poisson.exit_code == 0);
  REQUIRE(lattice.exit_code == 0);
  REQUIRE(flipped.exit_code == 0);
  REQUIRE(no_front.exit_code == 0);
  REQUIRE(front.exit_code == 0);
  REQUIRE(gmsh.exit_code == 0);
  CHECK(front.output.find("10 Lloyd iterations on exact cells") != std::string::npos);
  CHECK(front.output.find("exact dual (Delaunay of the seeds, no growth)") != std::string::npos);
  CHECK(front.output.find("2 smoothing sweeps") != std::string::npos);
  CHECK(logged(front.output, R"((\d+) from the fill)") == 0);
  // 78 boundary seeds; 138 Poisson-disc seeds (spacing 0.8), or 146 front
  // seeds (4 at the corners) and 3 lattice seeds where the fronts meet.
  // Gmsh: 208 nodes.
  CHECK(logged(no_front.output, R"(voronoi: metric iso[^:]*: (\d+) nodes)") == 216);
  CHECK(logged(front.output, R"((\d+) front \+)") == 146);
  CHECK(logged(front.output, R"(voronoi: metric iso[^:]*: (\d+) nodes)") == 227);
  const auto [min0, mean0] = quality(poisson.output, "Q11");
  const auto [min_lattice, mean_lattice] = quality(lattice.output, "Q11");
  const auto [min_flipped, mean_flipped] = quality(flipped.output, "Q11");
  const auto [min1, mean1] = quality(no_front.output, "Q11");
  const auto [min2, mean2] = quality(front.output, "Q11");
  const auto [min_gmsh, mean_gmsh] = quality(gmsh.output, "Q11");
  // Measured: Q11 min / mean 0.613 / 0.915 for Poisson-disc seeds alone,
  // 0.715 / 0.960 for lattice seeds alone, 0.613 / 0.914 with the edge flips
  // of the clean-up alone (the worst of each pair raised), 0.813 / 0.965 after
  // Lloyd and smoothing, 0.938 / 0.985 with the front (15 Lloyd steps and 3
  // smoothing sweeps: 0.813 / 0.969, 0.938 / 0.985; before the iso metric
  // came from Gmsh's mesh at twice the sizes: 0.626 / 0.915, 0.706 / 0.913
  // after the flips, 0.820 / 0.967 and 0.939 / 0.981);
  // Gmsh's default mesh of the same sizes 0.890 / 0.977 (docs/voronoi.md).
  CHECK(mean0 == Approx(0.912).margin(0.01));
  CHECK(mean_lattice > mean0 + 0.03);
  CHECK(min_lattice > min0 + 0.05);
  CHECK(mean_gmsh == Approx(0.977).margin(0.005));
  CHECK(min_flipped >= min0);
  CHECK(mean_flipped > mean0 - 0.005);
  CHECK(min1 > min0 + 0.15);
  CHECK(mean1 > mean0 + 0.04);
  CHECK(mean2 > mean1 + 0.01);
  CHECK(min2 > min1 + 0.05);
  CHECK(mean2 > mean_gmsh);
  CHECK(min2 > min_gmsh);
}

TEST_CASE("voronoi: the metric from a Gmsh tensor view, merged from a file or by the .geo",
          "[app][voronoi]") {
  const TempDir dir;
  const std::string out = dir / "view.msh";
  const std::string pos = dir / "metric.pos";
  const std::string with_view = dir / "view.geo";
  // Size 0.1 everywhere (M = 100 I) on two triangles over [-2, 2]^2, as in
  // the metric file test above: 80 boundary lines on the square, 32 on the hole.
  std::string tensor;
  for (int k = 0; k < 3; ++k) tensor += std::string(k ? "," : "") + "100,0,0,0,100,0,0,0,1";
  std::ofstream(pos) << "View \"metric\" {\nTT(-2,-2,0,2,-2,0,2,2,0){" << tensor
                     << "};\nTT(-2,-2,0,2,2,0,-2,2,0){" << tensor << "};\n};\n";
  const std::string lines = R"(voronoi: metric [^\n]*triangles, (\d+) boundary lines)";
  auto r = run_homesh(geo + "plate_hole.geo -m voronoi:metric=" + pos + " " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(logged(r.output, lines) > 105);
  std::ofstream(with_view) << "Include \"" << geo << "plate_hole.geo\";\nMerge \"" << pos
                           << "\";\n";
  r = run_homesh(with_view + " -m voronoi:metric=view0 " + out);
  REQUIRE(r.exit_code == 0);
  CHECK(logged(r.output, lines) > 105);
  r = run_homesh(with_view + " -m voronoi:metric=view3 " + out);
  CHECK(r.exit_code != 0);
  CHECK(r.output.find("metric view3: no view of tag 3 (1 views loaded)") != std::string::npos);
  std::ofstream(pos) << "View \"size\" {\nST(-2,-2,0,2,-2,0,2,2,0){1,1,1};\n};\n";
  r = run_homesh(geo + "plate_hole.geo -m voronoi:metric=" + pos + " " + out);
  CHECK(r.exit_code != 0);
  CHECK(r.output.find("1 components per value, a metric needs a tensor (9)") != std::string::npos);
}

TEST_CASE("voronoi: the default metric follows the .geo's background size field",
          "[app][voronoi]") {
  // A unit square whose Threshold field asks 0.01 within 0.05 of its centre, 0.08 beyond
  // 0.3 (nothing else sizes the mesh): iso takes its sizes from Gmsh's mesh of the .geo, so
  // a .geo user's fields size the crystals with no tensor view.
  const TempDir dir;
  const std::string in = dir / "field.geo", out = dir / "field.msh";
  std::ofstream(in) << R"(Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0}; Point(5) = {0.5, 0.5, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Curve("farfield") = {1, 2, 3, 4}; Physical Surface("fluid") = {1};
Field[1] = Distance; Field[1].PointsList = {5};
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = 0.01; Field[2].SizeMax = 0.08;
Field[2].DistMin = 0.05; Field[2].DistMax = 0.3;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
)";
  const auto r = run_homesh(in + " -m voronoi " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const homesh::Mesh m = read_output(out);
  // Mean edge length of the triangles by distance of their centroid from the centre.
  double near = 0, far = 0;
  int n_near = 0, n_far = 0;
  for (int t = 0; t < m.num_triangles(); ++t) {
    const Eigen::Vector2d a = m.x.col(m.tri(0, t)), b = m.x.col(m.tri(1, t)),
                          c = m.x.col(m.tri(2, t));
    const double d = ((a + b + c) / 3 - Eigen::Vector2d(0.5, 0.5)).norm();
    const double h = ((a - b).norm() + (b - c).norm() + (c - a).norm()) / 3;
    if (d < 0.04) {
      near += h;
      ++n_near;
    } else if (d > 0.35) {
      far += h;
      ++n_far;
    }
  }
  REQUIRE(n_near > 10);
  REQUIRE(n_far > 10);
  CAPTURE(near / n_near, far / n_far);
  // Within 20 % of the field (measured: 0.0102 and 0.0777).
  CHECK(near / n_near > 0.008);
  CHECK(near / n_near < 0.012);
  CHECK(far / n_far > 0.064);
  CHECK(far / n_far < 0.096);
}

TEST_CASE("voronoi and mesh follow the .geo's Mesh.MeshSizeFactor, and their factor options",
          "[app][voronoi]") {
  // The plate's sizes scaled by 0.5 in the .geo: about 4 times the
  // triangles for both meshers (they used to reset the factor to 1).
  const TempDir dir;
  const std::string out = dir / "factor.msh";
  const std::string finer = dir / "finer.geo";
  std::ofstream(finer) << "Include \"" << geo << "plate_hole.geo\";\nMesh.MeshSizeFactor = 0.5;\n";
  const auto triangles = [&](const std::string& input, const std::string& stage) {
    const auto r = run_homesh(input + " -m " + stage + " " + out);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return logged(r.output, stage.rfind("voronoi", 0) == 0
                                ? R"(voronoi: metric iso[^:]*: \d+ nodes, (\d+) triangles)"
                                : R"(mesh: \d+ nodes, (\d+) triangles)");
  };
  for (const std::string stage : {"voronoi", "mesh"}) {
    INFO(stage);
    const double plain = triangles(geo + "plate_hole.geo", stage);
    const double by_geo = triangles(finer, stage);
    const double by_option = triangles(geo + "plate_hole.geo", stage + ":factor=0.5");
    const double both = triangles(finer, stage + ":factor=1");
    CHECK(by_geo / plain == Approx(4).epsilon(0.2));
    CHECK(by_option / plain == Approx(4).epsilon(0.2));
    CHECK(both / plain == Approx(1).epsilon(0.05));  // the option wins over the .geo
  }
}
