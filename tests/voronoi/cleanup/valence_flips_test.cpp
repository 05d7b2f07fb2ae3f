#include "voronoi/cleanup/valence_flips.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "../voronoi_test_support.h"
#include "voronoi/cleanup/metric_smoothing.h"

using namespace homesh;

namespace {

constexpr int kSide = 7;  // lattice nodes per side

int node(int i, int j) { return i + kSide * j; }

// The equilateral lattice of kSide x kSide nodes (a rhombus of unit
// triangles), every interior node of valence 6; the nodes on the rhombus'
// sides are boundary nodes, its sides line elements.
Mesh lattice() {
  Mesh m;
  m.order = 1;
  m.x.resize(2, kSide * kSide);
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i) m.x.col(node(i, j)) << i + 0.5 * j, std::sqrt(3.0) / 2 * j;
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i) {
      const bool side = i == 0 || j == 0 || i == kSide - 1 || j == kSide - 1;
      m.node_class.push_back(NodeClass{side ? 1 : 2, 1, 0.0});
    }
  std::vector<std::array<int, 3>> t;
  for (int j = 0; j + 1 < kSide; ++j)
    for (int i = 0; i + 1 < kSide; ++i) {
      t.push_back({node(i, j), node(i + 1, j), node(i, j + 1)});
      t.push_back({node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)});
    }
  m.tri.resize(3, static_cast<Eigen::Index>(t.size()));
  for (std::size_t k = 0; k < t.size(); ++k) m.tri.col(k) << t[k][0], t[k][1], t[k][2];
  m.tri_entity.assign(t.size(), 1);
  std::vector<std::array<int, 2>> lines;
  for (int k = 0; k + 1 < kSide; ++k) {
    lines.push_back({node(k, 0), node(k + 1, 0)});
    lines.push_back({node(kSide - 1, k), node(kSide - 1, k + 1)});
    lines.push_back({node(k + 1, kSide - 1), node(k, kSide - 1)});
    lines.push_back({node(0, k + 1), node(0, k)});
  }
  m.line.resize(2, static_cast<Eigen::Index>(lines.size()));
  for (std::size_t k = 0; k < lines.size(); ++k) m.line.col(k) << lines[k][0], lines[k][1];
  m.line_entity.assign(lines.size(), 1);
  return m;
}

std::vector<char> interior(const Mesh& m) {
  std::vector<char> out;
  for (const NodeClass& c : m.node_class) out.push_back(c.dim == 2);
  return out;
}

std::vector<int> valences(const Mesh& m) {
  std::vector<int> v(m.num_nodes(), 0);
  for (Eigen::Index t = 0; t < m.tri.cols(); ++t)
    for (int k = 0; k < 3; ++k) ++v[m.tri(k, t)];
  return v;
}

// Flips the diagonal of cell (i, j): its two triangles become (p_ij,
// p_i+1j, p_i+1j+1) and (p_ij, p_i+1j+1, p_ij+1), 30-30-120 degrees (mean
// ratio 0.6), nodes (i, j) and (i+1, j+1) of valence 7, the others 5.
void flip_cell(Mesh& m, int i, int j) {
  const int cell = 2 * (i + (kSide - 1) * j);
  m.tri.col(cell) << node(i, j), node(i + 1, j), node(i + 1, j + 1);
  m.tri.col(cell + 1) << node(i, j), node(i + 1, j + 1), node(i, j + 1);
}

}  // namespace

TEST_CASE("valence flips: a flipped diagonal of the equilateral lattice is flipped back",
          "[voronoi]") {
  Mesh m = lattice();
  flip_cell(m, 2, 2);
  REQUIRE(valences(m)[node(2, 2)] == 7);
  REQUIRE(valences(m)[node(3, 2)] == 5);
  REQUIRE(test::euclidean_mean_ratio(m.triangle_nodes(2 * (2 + (kSide - 1) * 2))) == Approx(0.6));
  // Valence energy 4 -> 0; the new triangles (mean ratio 1) above the floor.
  CHECK(flip_to_regular_valence(m, interior(m), test::euclidean_mean_ratio, 0.7) == 1);
  const std::vector<int> v = valences(m);
  for (int k = 0; k < m.num_nodes(); ++k)
    if (m.node_class[k].dim == 2) CHECK(v[k] == 6);
  for (Eigen::Index t = 0; t < m.tri.cols(); ++t)
    CHECK(test::euclidean_mean_ratio(m.triangle_nodes(static_cast<int>(t))) == Approx(1.0));
  // The lattice itself is left alone: no flip lowers its energy.
  CHECK(flip_to_regular_valence(m, interior(m), test::euclidean_mean_ratio, 0.7) == 0);
}

TEST_CASE("valence flips: no flip below the floor, of a line, or with no interior node counted",
          "[voronoi]") {
  Mesh m = lattice();
  flip_cell(m, 2, 2);
  const Mesh flipped = m;
  // New triangles below the floor and below the 0.6 they would replace stay
  // unmade; at 0.65 (below the floor, above 0.6: the worst gets no worse) the
  // flip is made.
  const auto quality_of_new = [](double q) {
    return [q](const Eigen::Matrix<double, 2, 3>& X) {
      return test::euclidean_mean_ratio(X) > 0.99 ? q : test::euclidean_mean_ratio(X);
    };
  };
  CHECK(flip_to_regular_valence(m, interior(m), quality_of_new(0.55), 0.7) == 0);
  CHECK(flip_to_regular_valence(m, interior(m), quality_of_new(0.65), 0.7) == 1);
  m = flipped;
  // The diagonal as a line element (an embedded curve).
  m.line.conservativeResize(2, m.line.cols() + 1);
  m.line.col(m.line.cols() - 1) << node(2, 2), node(3, 3);
  m.line_entity.push_back(2);
  CHECK(flip_to_regular_valence(m, interior(m), test::euclidean_mean_ratio, 0.7) == 0);
  m = flipped;
  CHECK(flip_to_regular_valence(m, std::vector<char>(m.num_nodes(), 0), test::euclidean_mean_ratio,
                                0.7) == 0);
  CHECK(m.tri == flipped.tri);
  CHECK_THROWS(flip_to_regular_valence(m, {1, 0}, test::euclidean_mean_ratio, 0.7));
}
