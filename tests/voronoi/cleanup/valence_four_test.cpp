#include "voronoi/cleanup/valence_four.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "../voronoi_test_support.h"
#include "voronoi/cleanup/metric_smoothing.h"

using namespace homesh;

namespace {

// A centre node 4 with the four triangles of the quad 0 1 2 3 round it.
Mesh fan(const Eigen::Matrix<double, 2, 4>& quad, const Eigen::Vector2d& centre) {
  Mesh m;
  m.x.resize(2, 5);
  m.x.leftCols(4) = quad;
  m.x.col(4) = centre;
  m.node_class.assign(5, NodeClass{1, 1, 0.0});
  m.node_class[4] = NodeClass{2, 1, 0.0};
  m.tri.resize(3, 4);
  for (int k = 0; k < 4; ++k) m.tri.col(k) << 4, k, (k + 1) % 4;
  m.tri_entity.assign(4, 1);
  return m;
}

const std::vector<char> kCentreFree{0, 0, 0, 0, 1};

}  // namespace

TEST_CASE(
    "valence four: a node inside a 60-degree rhombus goes, its quad split by the short "
    "diagonal",
    "[voronoi]") {
  // Two equilateral triangles (mean ratio 1) without the centre; four
  // 30-60-90 triangles (mean ratio 4 sqrt 3 (sqrt 3 / 8) / (1 + 1/4 + 3/4) =
  // 0.75) with it.
  Eigen::Matrix<double, 2, 4> rhombus;
  rhombus << 0, 0.5, 0, -0.5,  //
      -std::sqrt(3.0) / 2, 0, std::sqrt(3.0) / 2, 0;
  Mesh m = fan(rhombus, Eigen::Vector2d::Zero());
  REQUIRE(test::euclidean_mean_ratio(m.triangle_nodes(0)) == Approx(0.75));
  const std::vector<int> gone = remove_valence_four(m, kCentreFree, test::euclidean_mean_ratio);
  CHECK(gone == std::vector<int>{4});
  REQUIRE(m.num_triangles() == 2);
  for (int t = 0; t < 2; ++t) {
    CHECK(test::euclidean_mean_ratio(m.triangle_nodes(t)) == Approx(1.0));
    for (int k = 0; k < 3; ++k) CHECK(m.tri(k, t) != 4);
  }
  CHECK(m.tri_entity == std::vector<int>{1, 1});
}

TEST_CASE("valence four: the centre of a square and a fixed node stay", "[voronoi]") {
  // The square's four right isosceles triangles are as good as its two.
  Eigen::Matrix<double, 2, 4> square;
  square << 1, 0, -1, 0,  //
      0, 1, 0, -1;
  Mesh m = fan(square, Eigen::Vector2d::Zero());
  CHECK(remove_valence_four(m, kCentreFree, test::euclidean_mean_ratio).empty());
  CHECK(m.num_triangles() == 4);
  // The rhombus again, but its centre not free.
  Eigen::Matrix<double, 2, 4> rhombus;
  rhombus << 0, 0.5, 0, -0.5,  //
      -std::sqrt(3.0) / 2, 0, std::sqrt(3.0) / 2, 0;
  Mesh fixed = fan(rhombus, Eigen::Vector2d::Zero());
  CHECK(remove_valence_four(fixed, std::vector<char>(5, 0), test::euclidean_mean_ratio).empty());
  CHECK(fixed.num_triangles() == 4);
}

TEST_CASE("valence four: in a dart only the split through its reflex corner is taken",
          "[voronoi]") {
  // Reflex at 1 (-0.2, 0): the diagonal 0-2 would fold (0, 1, 2); the other
  // gives two triangles of mean ratio 0.753 against the centre's worst 0.437.
  Eigen::Matrix<double, 2, 4> dart;
  dart << 0, -0.2, 0, -1,  //
      -1, 0, 1, 0;
  Mesh d = fan(dart, Eigen::Vector2d(-0.5, 0.0));
  CHECK(test::euclidean_mean_ratio(d.triangle_nodes(0)) == Approx(0.437).margin(1e-3));
  CHECK(remove_valence_four(d, kCentreFree, test::euclidean_mean_ratio) == std::vector<int>{4});
  REQUIRE(d.num_triangles() == 2);
  for (int t = 0; t < 2; ++t) {
    CHECK(test::euclidean_mean_ratio(d.triangle_nodes(t)) == Approx(0.753).margin(1e-3));
    CHECK((d.tri.col(t).array() == 1).any());  // both on the diagonal 1-3
    CHECK((d.tri.col(t).array() == 3).any());
  }
}
