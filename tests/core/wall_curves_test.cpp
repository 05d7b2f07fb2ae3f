#include "core/wall_curves.h"

#include <catch2/catch.hpp>

#include "core/error.h"

using namespace homesh;

namespace {

// Curves 1..4 on the lines, 1 and 2 in the group "hole" (number 7), 3 in
// "farfield" (number 2), 4 in no group.
Mesh grouped_curves() {
  Mesh m;
  m.entities = {{1, 1, {}}, {1, 2, {}}, {1, 3, {}}, {1, 4, {}}, {2, 1, {1, 2, 3, 4}}};
  m.physicals = {{1, 7, "hole", {1, 2}}, {1, 2, "farfield", {3}}, {2, 3, "plate", {1}}};
  return m;
}

}  // namespace

TEST_CASE("walls are named by physical group name or number, or by curve tag", "[core]") {
  const Mesh m = grouped_curves();
  CHECK(wall_curves(m, {"hole"}) == std::vector<int>{1, 2});
  CHECK(wall_curves(m, {"7"}) == std::vector<int>{1, 2});
  CHECK(wall_curves(m, {"4"}) == std::vector<int>{4});
  // A group number comes before a curve tag: 2 is farfield's number.
  CHECK(wall_curves(m, {"2"}) == std::vector<int>{3});
  CHECK(wall_curves(m, {"farfield", "hole", "1"}) == std::vector<int>{1, 2, 3});
  // 3 is the number of a surface group and a curve tag: the curve.
  CHECK(wall_curves(m, {"3"}) == std::vector<int>{3});
  CHECK_THROWS_WITH(wall_curves(m, {"plate"}, "stage 'rotate'"),
                    "stage 'rotate': no wall 'plate': not a curve physical group (hole, farfield) "
                    "by name or number, nor a curve tag of the mesh");
  CHECK_THROWS_WITH(wall_curves(m, {"9"}), Catch::Contains("layers: no wall '9'"));
  CHECK_THROWS_WITH(wall_curves(m, {}), Catch::Contains("no walls given"));
}
