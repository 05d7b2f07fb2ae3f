// homesh's views as Gmsh shows them: styled in the process when added, and the
// same in a Gmsh that opens the written file, however many files it merges.
#include "gmsh/view_style.h"

#include <gmsh.h>

#include <catch2/catch.hpp>
#include <string>

#include "../support/gmsh_session.h"
#include "../support/temp_dir.h"
#include "gmsh/read_model.h"
#include "gmsh/views.h"
#include "gmsh/write_model.h"
#include "gmsh/write_msh.h"

using namespace homesh;

namespace {

double view_option(int index, const std::string& name) {
  double value = 0;
  gmsh::option::getNumber("View[" + std::to_string(index) + "]." + name, value);
  return value;
}

std::string view_name(int index) {
  std::string name;
  gmsh::option::getString("View[" + std::to_string(index) + "].Name", name);
  return name;
}

int num_views() {
  std::vector<int> tags;
  gmsh::view::getTags(tags);
  return static_cast<int>(tags.size());
}

// A shown quality field `prefix` valid, a hidden one `prefix` index (not a quality).
std::vector<Field> fields(const std::string& prefix, int triangles) {
  Field valid{prefix + " valid", Field::Kind::Element, Eigen::MatrixXd::Constant(1, triangles, 0.5),
              true, true};
  Field index{prefix + " index", Field::Kind::Element, Eigen::MatrixXd::Zero(1, triangles), false};
  for (int e = 0; e < triangles; ++e) index.values(0, e) = e;
  return {valid, index};
}

}  // namespace

TEST_CASE("element data covers every element, neutral off the triangles", "[gmsh]") {
  test::GmshSession session;
  test::make_plate_with_hole(3);
  const Mesh m = gmsh_adapter::read_model("plate");
  const auto tags = gmsh_adapter::write_model(m);
  const auto views = gmsh_adapter::add_views(fields("a", m.num_triangles()), tags);
  const std::size_t all = tags.first_triangle - 1 + static_cast<std::size_t>(m.num_triangles());
  REQUIRE(tags.first_triangle > 1);  // points and lines come first
  for (int k = 0; k < 2; ++k) {
    std::string type;
    std::vector<std::size_t> element_tags;
    std::vector<std::vector<double>> data;
    double time;
    int components;
    gmsh::view::getModelData(views[k], 0, type, element_tags, data, time, components);
    REQUIRE(type == "ElementData");
    REQUIRE(element_tags.size() == all);
    for (std::size_t i = 0; i < all; ++i) {
      REQUIRE(element_tags[i] == i + 1);
      const double expected = element_tags[i] < tags.first_triangle
                                  ? (k == 0 ? 1.0 : 0.0)
                                  : (k == 0 ? 0.5 : double(element_tags[i] - tags.first_triangle));
      REQUIRE(data[i][0] == expected);
    }
  }
}

TEST_CASE("views are styled when added: one shown on [0, 1], curved by uniform refinement",
          "[gmsh]") {
  test::GmshSession session;
  test::make_plate_with_hole(3);
  const Mesh m = gmsh_adapter::read_model("plate");
  const auto tags = gmsh_adapter::write_model(m);
  gmsh_adapter::add_views(fields("a", m.num_triangles()), tags);
  REQUIRE(view_option(0, "Visible") == 1);
  REQUIRE(view_option(1, "Visible") == 0);
  REQUIRE(view_option(0, "RangeType") == 2);
  REQUIRE(view_option(0, "CustomMin") == 0);
  REQUIRE(view_option(0, "CustomMax") == 1);
  REQUIRE(view_option(1, "RangeType") == 1);  // not a quality: its own range
  for (int i = 0; i < 2; ++i) {
    REQUIRE(view_option(i, "AdaptVisualizationGrid") == 1);
    REQUIRE(view_option(i, "TargetError") < 0);
    REQUIRE(view_option(i, "MaxRecursionLevel") == 3);
    REQUIRE(view_option(i, "DrawLines") == 0);
  }
  // Views added later with a shown one: the earlier ones are hidden.
  gmsh_adapter::add_views(fields("b", m.num_triangles()), tags);
  REQUIRE(view_option(0, "Visible") == 0);
  REQUIRE(view_option(2, "Visible") == 1);
  REQUIRE(view_option(3, "Visible") == 0);
}

TEST_CASE("two homesh files merged in Gmsh: each styled by its own sidecar", "[gmsh]") {
  test::GmshSession session;
  const test::TempDir dir;
  const std::string a = dir / "a.msh", b = dir / "b.msh";
  for (const std::string& path : {a, b}) {
    gmsh::clear();
    test::make_plate_with_hole(path == a ? 2 : 3);
    const Mesh m = gmsh_adapter::read_model("plate");
    const auto tags = gmsh_adapter::write_model(m);
    const std::string prefix = path == a ? "a" : "b";
    gmsh_adapter::write_msh(path, gmsh_adapter::add_views(fields(prefix, m.num_triangles()), tags),
                            "test");
  }
  gmsh::clear();
  gmsh::open(a);
  REQUIRE(num_views() == 2);
  REQUIRE(view_name(0) == "a valid");
  REQUIRE(view_option(0, "Visible") == 1);
  REQUIRE(view_option(0, "MaxRecursionLevel") == 2);  // order 2
  gmsh::view::add("the user's own view");             // index 2: b's views come after it
  gmsh::model::add("b");  // as `gmsh a.msh -new b.msh`: homesh files share element tags
  gmsh::merge(b);
  REQUIRE(num_views() == 5);
  REQUIRE(view_name(3) == "b valid");
  REQUIRE(view_name(4) == "b index");
  // b's views styled as b's sidecar says; those loaded before left as they were, but hidden.
  for (int i = 0; i < 5; ++i) REQUIRE(view_option(i, "Visible") == (i == 3 ? 1 : 0));
  REQUIRE(view_option(0, "MaxRecursionLevel") == 2);
  REQUIRE(view_option(3, "MaxRecursionLevel") == 3);
  REQUIRE(view_option(3, "RangeType") == 2);
  REQUIRE(view_option(4, "RangeType") == 1);
  for (int i : {0, 1, 3, 4}) REQUIRE(view_option(i, "TargetError") < 0);
}
