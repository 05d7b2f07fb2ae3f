#include "pipeline/group_context_by_entity.h"

#include <catch2/catch.hpp>

using namespace homesh;

TEST_CASE("elements regrouped by entity, stably, fields permuted with the triangles",
          "[pipeline]") {
  Context ctx;
  Mesh m;
  m.x = Eigen::Matrix2Xd::Zero(2, 6);
  m.tri.resize(3, 5);
  m.tri << 0, 1, 2, 3, 4,  //
      1, 2, 3, 4, 5,       //
      2, 3, 4, 5, 0;
  m.tri_entity = {2, 1, 2, 1, 1};  // as the layers stage leaves two surfaces
  m.line.resize(2, 3);
  m.line << 0, 1, 2, 1, 2, 3;
  m.line_entity = {7, 5, 7};
  m.point_node = {0, 3};
  m.point_entity = {4, 4};
  ctx.mesh = m;
  Field element{"e", Field::Kind::Element, Eigen::MatrixXd(1, 5)};
  element.values << 10, 11, 12, 13, 14;
  Field node{"n", Field::Kind::ElementNode, element.values.replicate(3, 1)};
  Field some{"s", Field::Kind::ElementNode, Eigen::MatrixXd::Zero(3, 2)};
  some.elements = {0, 3};
  ctx.fields = {element, node, some};

  group_context_by_entity(ctx);
  const Mesh& g = *ctx.mesh;
  // Stable: triangles 1, 3, 4 (entity 1), then 0, 2 (entity 2).
  REQUIRE(g.tri_entity == std::vector<int>{1, 1, 1, 2, 2});
  REQUIRE(g.tri.row(0) == (Eigen::RowVectorXi(5) << 1, 3, 4, 0, 2).finished());
  REQUIRE(ctx.fields[0].values == (Eigen::MatrixXd(1, 5) << 11, 13, 14, 10, 12).finished());
  REQUIRE(ctx.fields[1].values == ctx.fields[0].values.replicate(3, 1));
  REQUIRE(ctx.fields[2].elements == std::vector<int>{3, 1});  // old 0 and 3, where they went
  REQUIRE(g.line_entity == std::vector<int>{5, 7, 7});
  REQUIRE(g.line.col(0) == m.line.col(1));
  REQUIRE(g.line.col(1) == m.line.col(0));
  REQUIRE(g.point_node == m.point_node);

  // Grouped already: nothing moves.
  const Mesh before = *ctx.mesh;
  group_context_by_entity(ctx);
  REQUIRE(ctx.mesh->tri == before.tri);
  REQUIRE(ctx.fields[0].values == (Eigen::MatrixXd(1, 5) << 11, 13, 14, 10, 12).finished());
}
