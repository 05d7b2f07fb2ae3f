#include "voronoi/cleanup/valence_three.h"

#include <algorithm>
#include <catch2/catch.hpp>

using namespace homesh;

TEST_CASE("valence three: an interior node of three triangles goes, their union stays",
          "[voronoi]") {
  // Triangle 0 1 2 split at node 3 (interior), beside triangle 1 0 4.
  std::vector<std::array<int, 3>> t{{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}};
  std::vector<int> surface{7, 7, 7, 7};
  std::vector<char> interior{0, 0, 0, 1, 0};
  CHECK(remove_valence_three(t, surface, interior) == 1);
  REQUIRE(t.size() == 2);
  CHECK(t[0] == std::array<int, 3>{1, 0, 4});
  // The union, counter-clockwise as its parts (a rotation of 0 1 2).
  std::array<int, 3> u = t[1];
  std::rotate(u.begin(), std::find(u.begin(), u.end(), 0), u.end());
  CHECK(u == std::array<int, 3>{0, 1, 2});
  CHECK(surface == std::vector<int>{7, 7});

  SECTION("not when the node is on the boundary, or its triangles lie on two surfaces") {
    std::vector<std::array<int, 3>> s{{0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    std::vector<int> two{1, 1, 2};
    CHECK(remove_valence_three(s, two, interior) == 0);
    std::vector<int> one{1, 1, 1};
    CHECK(remove_valence_three(s, one, std::vector<char>(5, 0)) == 0);
    CHECK(s.size() == 3);
  }
  SECTION("again where a removal leaves another node of three triangles") {
    // Node 4 inside 0 1 2 with four triangles: 0 1 4, 1 2 4 split at 5 (interior) into
    // 1 2 5, 2 4 5, 4 1 5; and 2 0 4. Removing 5 leaves 4 with three.
    std::vector<std::array<int, 3>> s{{0, 1, 4}, {1, 2, 5}, {2, 4, 5}, {4, 1, 5}, {2, 0, 4}};
    std::vector<int> one(5, 0);
    std::vector<char> inner{0, 0, 0, 0, 1, 1};
    CHECK(remove_valence_three(s, one, inner) == 2);
    REQUIRE(s.size() == 1);
    std::rotate(s[0].begin(), std::find(s[0].begin(), s[0].end(), 0), s[0].end());
    CHECK(s[0] == std::array<int, 3>{0, 1, 2});
  }
}
