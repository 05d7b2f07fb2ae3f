#include "core/check_mesh.h"

#include <catch2/catch.hpp>
#include <limits>

#include "core/error.h"
#include "quality/mesh_validity.h"

using namespace homesh;

namespace {

// Two counter-clockwise triangles on the unit square.
Mesh square() {
  Mesh m;
  m.x.resize(2, 5);
  m.x << 0, 1, 1, 0, 0.5, 0, 0, 1, 1, 0;
  m.node_class.resize(5);
  m.tri.resize(3, 2);
  m.tri << 0, 0, 1, 2, 2, 3;
  m.tri_entity = {1, 1};
  return m;
}

}  // namespace

TEST_CASE("check_mesh accepts a good mesh and names each defect", "[core]") {
  Mesh m = square();
  REQUIRE_NOTHROW(check_mesh(m, "in.msh"));

  Mesh inverted = square();
  std::swap(inverted.tri(1, 1), inverted.tri(2, 1));
  REQUIRE_THROWS_WITH(check_mesh(inverted, "in.msh"),
                      "in.msh: triangle 2 at (0.333333, 0.666667) is inverted (its corners run "
                      "clockwise)");

  Mesh flat = square();
  flat.tri.col(1) << 0, 4, 1;  // (0,0), (0.5,0), (1,0): collinear
  REQUIRE_THROWS_WITH(check_mesh(flat, "in.msh"),
                      Catch::Contains("triangle 2") && Catch::Contains("zero area"));

  Mesh repeated = square();
  repeated.tri.col(1) << 0, 2, 2;
  REQUIRE_THROWS_WITH(check_mesh(repeated, "in.msh"), Catch::Contains("repeats a corner"));

  Mesh duplicate = square();
  duplicate.tri.col(1) << 1, 2, 0;  // same corners as triangle 1, rotated
  REQUIRE_THROWS_WITH(check_mesh(duplicate, "in.msh"),
                      Catch::Contains("triangle 2") && Catch::Contains("duplicates"));

  Mesh fin = square();  // a third triangle on the diagonal 1-3
  fin.tri.conservativeResize(3, 3);
  fin.tri.col(2) << 2, 0, 4;
  fin.tri_entity.push_back(1);
  REQUIRE_THROWS_WITH(check_mesh(fin, "in.msh"),
                      Catch::Contains("the edge between nodes 1 and 3") &&
                          Catch::Contains("three or more elements (a non-manifold mesh)"));

  Mesh far = square();
  far.x *= 1e13;
  REQUIRE_THROWS_WITH(check_mesh(far, "in.msh"),
                      "in.msh: node 2 lies 1e+13 from the origin; homesh accepts coordinates up "
                      "to 1e+12");

  Mesh nan = square();
  nan.x(1, 3) = std::numeric_limits<double>::quiet_NaN();
  REQUIRE_THROWS_WITH(check_mesh(nan, "in.msh"), "in.msh: node 4 has a non-finite coordinate");
}

TEST_CASE("check_mesh is scale-free: tiny and huge meshes pass", "[core]") {
  for (double s : {1e-8, 1e8}) {
    Mesh m = square();
    m.x *= s;
    REQUIRE_NOTHROW(check_mesh(m, "in.msh"));
  }
}

TEST_CASE("check_mesh checks quadrilaterals and edges shared with triangles", "[core]") {
  // The unit square as one quadrilateral, a triangle on its top edge.
  Mesh m;
  m.x.resize(2, 5);
  m.x << 0, 1, 1, 0, 0.5, 0, 0, 1, 1, 2;
  m.node_class.resize(5);
  m.quad.resize(4, 1);
  m.quad << 0, 1, 2, 3;
  m.quad_entity = {1};
  m.tri.resize(3, 1);
  m.tri << 3, 2, 4;
  m.tri_entity = {1};
  REQUIRE_NOTHROW(check_mesh(m, "in.msh"));

  Mesh inverted = m;
  inverted.quad.col(0) << 0, 3, 2, 1;
  REQUIRE_THROWS_WITH(check_mesh(inverted, "in.msh"),
                      "in.msh: quadrilateral 1 at (0.5, 0.5) is inverted (its corners run "
                      "clockwise)");
  Mesh repeated = m;
  repeated.quad.col(0) << 0, 1, 2, 1;
  REQUIRE_THROWS_WITH(check_mesh(repeated, "in.msh"), Catch::Contains("repeats a corner node"));
  Mesh third = m;  // a second triangle on the edge 3-2 the quadrilateral and triangle share
  third.x.conservativeResize(2, 6);
  third.x.col(5) << 0.5, 3;
  third.node_class.resize(6);
  third.tri.conservativeResize(3, 2);
  third.tri.col(1) << 3, 2, 5;
  third.tri_entity.push_back(1);
  REQUIRE_THROWS_WITH(check_mesh(third, "in.msh"),
                      Catch::Contains("three or more elements (a non-manifold mesh)"));
}

TEST_CASE(
    "check_mesh refuses a curved triangle as inverted only if its boundary runs clockwise too",
    "[mesh]") {
  // P2: the straight triangle (0, 0), (1, 0), (0.5, 0.05) and its edge nodes
  // bent round the unit circle, (x, y) -> ((1 - y) sin x, 1 - (1 - y) cos x)
  // (orientation-preserving), 6 decimals. The corners now run clockwise (the
  // third lies beyond the chord of the first two, the arc's sag 0.12 being
  // over the height 0.05) while det J > 0 all over (Gmsh order: corners,
  // then the nodes of edges 0-1, 1-2, 2-0), as at p = 3 round a leading edge.
  Mesh m;
  m.order = 2;
  m.x.resize(2, 6);
  m.x << 0, 0.841471, 0.455454, 0.479426, 0.664598, 0.241219,  //
      0, 0.459698, 0.166297, 0.122417, 0.286603, 0.055310;
  m.node_class.resize(6);
  m.tri.resize(6, 1);
  m.tri << 0, 1, 2, 3, 4, 5;
  m.tri_entity = {1};
  const Eigen::Vector2d u = m.x.col(1) - m.x.col(0), v = m.x.col(2) - m.x.col(0);
  REQUIRE(u.x() * v.y() - u.y() * v.x() < 0);  // the corners clockwise
  CHECK(mesh_validity(m).invalid == 0);        // certified by its Bezier bounds
  REQUIRE_NOTHROW(check_mesh(m, "in.msh"));
  // Its mirror image: corners counter-clockwise, folded all over, left to
  // the certification, which finds it invalid.
  Mesh mirrored = m;
  mirrored.x.row(1) *= -1;
  REQUIRE_NOTHROW(check_mesh(mirrored, "in.msh"));
  CHECK(mesh_validity(mirrored).invalid == 1);
  // A straight P2 triangle listed clockwise, corners and boundary: refused.
  Mesh straight = m;
  straight.x << 0, 1, 0.5, 0.5, 0.75, 0.25,  //
      0, 0, -0.1, 0, -0.05, -0.05;
  REQUIRE_THROWS_WITH(check_mesh(straight, "in.msh"),
                      "in.msh: triangle 1 at (0.5, -0.0333333) is inverted (its corners run "
                      "clockwise)");
}

TEST_CASE("check_mesh names the non-manifold edge whose third use comes first", "[core]") {
  // Two edges with three triangles each, 2-3 (nodes 3 and 4, 1-based) full at
  // triangle 3, 0-1 only at triangle 6: the edge named is 2-3, though node 0's
  // edges come first by node.
  Mesh m;
  m.x.resize(2, 8);
  m.x << 0, 1, 0, 1, 0.5, 0.5, 0.5, 0.5,  //
      0, 0, 2, 2, 1, 3, -1, 0.5;
  m.node_class.resize(8);
  m.tri.resize(3, 6);
  m.tri << 3, 2, 3, 0, 0, 1,  //
      2, 3, 2, 1, 1, 0,       //
      4, 5, 7, 4, 7, 6;
  m.tri_entity.assign(6, 1);
  REQUIRE_THROWS_WITH(check_mesh(m, "in.msh"),
                      Catch::Contains("the edge between nodes 3 and 4 of triangle 3 ") &&
                          Catch::Contains("non-manifold"));
  // A fourth use of 2-3 after it changes nothing.
  Mesh fourth = m;
  fourth.tri.conservativeResize(3, 7);
  fourth.tri.col(6) << 3, 2, 6;
  fourth.tri_entity.push_back(1);
  REQUIRE_THROWS_WITH(check_mesh(fourth, "in.msh"),
                      Catch::Contains("the edge between nodes 3 and 4 of triangle 3 "));
  // The same triangles, those on 0-1 first: 0-1 is named.
  Mesh swapped = m;
  swapped.tri.leftCols(3).swap(swapped.tri.rightCols(3));
  REQUIRE_THROWS_WITH(check_mesh(swapped, "in.msh"),
                      Catch::Contains("the edge between nodes 1 and 2 of triangle 3 "));
}
