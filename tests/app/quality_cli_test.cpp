// The quality stage and the validity guard on output, run as a user does.
#include <gmsh.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <regex>

#include "../support/gmsh_session.h"
#include "../support/run_command.h"
#include "../support/temp_dir.h"
#include "gmsh/read_model.h"
#include "gmsh/write_model.h"

using homesh::test::run_homesh;
using homesh::test::TempDir;

namespace {

using homesh::test::geo;

// A quadratic plate-with-hole mesh with one interior edge node pushed far
// across its triangles, written in DIR: corners fine, curved elements invalid.
std::string write_invalid_mesh(const TempDir& dir) {
  const std::string path = dir / "invalid_input.msh";
  homesh::test::GmshSession session;
  gmsh::open(geo + "plate_hole.geo");
  gmsh::model::mesh::generate(2);
  gmsh::model::mesh::setOrder(2);
  homesh::Mesh m = homesh::gmsh_adapter::read_model("plate");
  std::vector<bool> corner(m.num_nodes(), false);
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int k = 0; k < 3; ++k) corner[m.tri(k, e)] = true;
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_class[i].dim == 2 && !corner[i]) {  // an interior edge node
      m.x(0, i) += 0.5;
      break;
    }
  homesh::gmsh_adapter::write_model(m);
  gmsh::write(path);
  return path;
}

}  // namespace

TEST_CASE("quality stage: certified validity, views and a report", "[app]") {
  const TempDir dir;
  const std::string out = dir / "quality.msh";
  const auto r =
      run_homesh(geo + "plate_hole.geo -m mesh -m order:p=3 -m quality:measures=Q4,Q6 " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.output.find("validity: 0 invalid of") != std::string::npos);
  REQUIRE(std::regex_search(r.output, std::regex(R"(Q6\s+min 0\.\d+)")));
  homesh::test::GmshSession session;
  gmsh::open(out);
  std::vector<int> views;
  gmsh::view::getTags(views);
  REQUIRE(views.size() == 5);  // minJ/maxJ, Q4 and Q6 (element minimum, at nodes); none poor
  std::vector<std::string> names;
  for (int v : views) {
    std::string name;
    gmsh::option::getString("View[" + std::to_string(gmsh::view::getIndex(v)) + "].Name", name);
    names.push_back(name);
  }
  REQUIRE(names == std::vector<std::string>{"homesh: certified minJ/maxJ",
                                            "homesh: Q4 Equal volume, element minimum",
                                            "homesh: Q4 Equal volume, at nodes",
                                            "homesh: Q6 Smoothness, element minimum",
                                            "homesh: Q6 Smoothness, at nodes"});
}

TEST_CASE("poor elements: a view of their own, found by the tags the report gives", "[app]") {
  const TempDir dir;
  const std::string in = write_invalid_mesh(dir), out = dir / "poor.msh";
  const auto r = run_homesh(in + " -m quality:poor=0.5 --keep-invalid " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  std::smatch worst;
  REQUIRE(std::regex_search(r.output, worst,
                            std::regex(R"(worst minJ/maxJ (-?[0-9.]+) at triangle (\d+))")));
  homesh::test::GmshSession session;
  gmsh::open(out);
  std::vector<int> views;
  gmsh::view::getTags(views);
  const auto data = [](int view) {
    std::string type;
    std::vector<std::size_t> tags;
    std::vector<std::vector<double>> values;
    double time;
    int components;
    gmsh::view::getModelData(view, 0, type, tags, values, time, components);
    std::map<std::size_t, double> by_tag;
    for (std::size_t k = 0; k < tags.size(); ++k) by_tag[tags[k]] = values[k][0];
    return by_tag;
  };
  const auto validity = data(views.front());
  std::map<std::size_t, double> below;
  for (const auto& [tag, value] : validity)
    if (value < 0.5) below[tag] = value;
  REQUIRE(!below.empty());
  const int poor = views.back();
  std::string name;
  gmsh::option::getString("View[" + std::to_string(gmsh::view::getIndex(poor)) + "].Name", name);
  REQUIRE(name == "homesh: elements of certified minJ/maxJ < 0.5");
  REQUIRE(data(poor) == below);
  // The report's worst triangle is a Gmsh element tag: a triangle of the file, holding the worst.
  const std::size_t tag = std::stoul(worst[2]);
  int type = 0;
  std::vector<std::size_t> nodes;
  gmsh::model::mesh::getElement(tag, type, nodes);
  REQUIRE(type == gmsh::model::mesh::getElementType("Triangle", 2));
  REQUIRE(validity.at(tag) == Approx(std::stod(worst[1])).margin(1e-4));
  for (const auto& [t, value] : validity) REQUIRE(value >= validity.at(tag));
}

TEST_CASE("an invalid mesh is never written silently", "[app]") {
  const TempDir dir;
  const std::string in = write_invalid_mesh(dir), out = dir / "invalid_output.msh";
  auto r = run_homesh(in + " -m quality " + out);
  INFO(r.output);
  REQUIRE(r.exit_code != 0);
  REQUIRE(std::regex_search(r.output, std::regex(R"(validity: [1-9]\d* invalid of)")));
  REQUIRE(r.output.find("not certified valid (keep them with --keep-invalid)") !=
          std::string::npos);
  REQUIRE_FALSE(std::ifstream(out).good());
  r = run_homesh("--keep-invalid " + in + " " + out);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.output.find("warning: " + out + ": writing") != std::string::npos);
  REQUIRE(std::ifstream(out).good());
}

TEST_CASE("quality on a mixed quadrilateral and triangle mesh: views over every element",
          "[app][quads]") {
  const TempDir dir;
  const std::string in = dir / "mixed.msh", out = dir / "mixed_quality.msh";
  int triangles = 0, quads = 0;
  {
    homesh::test::GmshSession session;
    homesh::test::make_plate_with_quad_layer(3);
    const homesh::Mesh m = homesh::gmsh_adapter::read_model("plate");
    triangles = m.num_triangles();
    quads = m.num_quads();
    gmsh::write(in);
  }
  REQUIRE(quads > 20);
  const auto r = run_homesh(in + " -m quality:measures=Q1,Q4,Q11:worst=3 --keep-invalid " + out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.output.find("of " + std::to_string(triangles) + " triangles and " +
                        std::to_string(quads) + " quadrilaterals") != std::string::npos);
  homesh::test::GmshSession session;
  gmsh::open(out);
  std::vector<std::size_t> tags2d;
  REQUIRE(homesh::gmsh_adapter::read_model(out, &tags2d).num_quads() == quads);
  const int quad_nodes = 16, triangle_nodes = 10;  // order 3
  std::vector<int> views;
  gmsh::view::getTags(views);
  REQUIRE(views.size() >= 7);  // minJ/maxJ, 3 measures (element minimum, at nodes)[, poor]
  for (int view : views) {
    std::string name, type;
    gmsh::option::getString("View[" + std::to_string(gmsh::view::getIndex(view)) + "].Name", name);
    INFO(name);
    std::vector<std::size_t> tags;
    std::vector<std::vector<double>> values;
    double time;
    int components;
    gmsh::view::getModelData(view, 0, type, tags, values, time, components);
    std::map<std::size_t, const std::vector<double>*> by_tag;
    for (std::size_t k = 0; k < tags.size(); ++k) by_tag[tags[k]] = &values[k];
    if (name.find("certified minJ/maxJ <") != std::string::npos) continue;  // a few elements
    std::size_t covered = 0;
    for (std::size_t e = 0; e < tags2d.size(); ++e) {
      const auto it = by_tag.find(tags2d[e]);
      if (it == by_tag.end()) continue;
      ++covered;
      const std::vector<double>& v = *it->second;
      const bool quad = e >= static_cast<std::size_t>(triangles);
      if (type == "ElementNodeData")
        REQUIRE(v.size() == static_cast<std::size_t>(quad ? quad_nodes : triangle_nodes));
      for (double x : v) REQUIRE((x <= 1.0 && std::isfinite(x)));
    }
    REQUIRE(covered == tags2d.size());
  }
}
