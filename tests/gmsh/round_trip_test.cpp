#include <gmsh.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <fstream>
#include <limits>
#include <map>
#include <string>

#include "../support/gmsh_session.h"
#include "../support/temp_dir.h"
#include "element/quad_reference_nodes.h"
#include "gmsh/read_model.h"
#include "gmsh/view_style.h"
#include "gmsh/views.h"
#include "gmsh/write_model.h"
#include "gmsh/write_msh.h"

using namespace homesh;

namespace {

// Coordinates agree to `tol` (0 in memory; Gmsh writes 16 significant digits).
void require_same(const Mesh& a, const Mesh& b, double tol = 0) {
  REQUIRE(a.order == b.order);
  REQUIRE(a.x.cols() == b.x.cols());
  REQUIRE((a.x - b.x).cwiseAbs().maxCoeff() <= tol);
  REQUIRE(a.tri == b.tri);
  REQUIRE(a.tri_entity == b.tri_entity);
  REQUIRE(a.quad == b.quad);
  REQUIRE(a.quad_entity == b.quad_entity);
  REQUIRE(a.line == b.line);
  REQUIRE(a.line_entity == b.line_entity);
  REQUIRE(a.point_node == b.point_node);
  REQUIRE(a.point_entity == b.point_entity);
  REQUIRE(a.node_class.size() == b.node_class.size());
  for (std::size_t i = 0; i < a.node_class.size(); ++i) {
    REQUIRE(a.node_class[i].dim == b.node_class[i].dim);
    REQUIRE(a.node_class[i].tag == b.node_class[i].tag);
  }
  REQUIRE(a.entities.size() == b.entities.size());
  for (std::size_t i = 0; i < a.entities.size(); ++i) {
    REQUIRE(a.entities[i].dim == b.entities[i].dim);
    REQUIRE(a.entities[i].tag == b.entities[i].tag);
  }
  REQUIRE(a.physicals.size() == b.physicals.size());
  for (std::size_t i = 0; i < a.physicals.size(); ++i) {
    REQUIRE(a.physicals[i].name == b.physicals[i].name);
    REQUIRE(a.physicals[i].dim == b.physicals[i].dim);
    REQUIRE(a.physicals[i].entities == b.physicals[i].entities);
  }
}

std::size_t gmsh_count(int dim) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes, dim);
  std::size_t n = 0;
  for (const auto& t : tags) n += t.size();
  return n;
}

}  // namespace

TEST_CASE("model -> core -> model -> .msh -> model keeps everything, p = 1..6", "[gmsh]") {
  for (int p = 1; p <= 6; ++p) {
    CAPTURE(p);
    test::GmshSession session;
    test::make_plate_with_hole(p);
    std::vector<std::size_t> node_tags;
    std::vector<double> coord, param;
    gmsh::model::mesh::getNodes(node_tags, coord, param);
    const std::size_t lines = gmsh_count(1), tris = gmsh_count(2), points = gmsh_count(0);

    const Mesh m1 = gmsh_adapter::read_model("plate");
    REQUIRE(m1.order == p);
    REQUIRE(static_cast<std::size_t>(m1.num_nodes()) == node_tags.size());
    REQUIRE(static_cast<std::size_t>(m1.num_triangles()) == tris);
    REQUIRE(static_cast<std::size_t>(m1.num_lines()) == lines);
    REQUIRE(m1.point_node.size() == points);
    REQUIRE(m1.tri.rows() == (p + 1) * (p + 2) / 2);
    REQUIRE(m1.physicals.size() == 2);

    const auto tags = gmsh_adapter::write_model(m1);
    require_same(m1, gmsh_adapter::read_model("plate"));

    Field f{"node index", Field::Kind::ElementNode, m1.tri.cast<double>()};
    const auto views = gmsh_adapter::add_views({f}, tags);
    const test::TempDir dir;
    const std::string path = dir / "round_trip.msh";
    gmsh_adapter::write_msh(path, views, "test provenance");

    gmsh::clear();
    gmsh::open(path);
    const Mesh m3 = gmsh_adapter::read_model(path);
    require_same(m1, m3, 1e-15);
    std::vector<int> view_tags;
    gmsh::view::getTags(view_tags);
    REQUIRE(view_tags.size() == 1);
    std::string type;
    std::vector<std::size_t> element_tags;
    std::vector<std::vector<double>> data;
    double time;
    int components;
    gmsh::view::getModelData(view_tags[0], 0, type, element_tags, data, time, components);
    REQUIRE(type == "ElementNodeData");
    REQUIRE(element_tags.size() == static_cast<std::size_t>(m1.num_triangles()));
    for (std::size_t k = 0; k < element_tags.size(); ++k) {
      const auto e = static_cast<Eigen::Index>(element_tags[k] - tags.first_triangle);
      REQUIRE(data[k].size() == static_cast<std::size_t>(m1.tri.rows()));
      for (Eigen::Index i = 0; i < m1.tri.rows(); ++i) REQUIRE(data[k][i] == m1.tri(i, e));
    }
  }
}

TEST_CASE("write_msh records provenance and a sidecar of the views' styles", "[gmsh]") {
  test::GmshSession session;
  test::make_plate_with_hole(2);
  const Mesh m = gmsh_adapter::read_model("plate");
  const auto tags = gmsh_adapter::write_model(m);
  Field a{"a", Field::Kind::Element, Eigen::MatrixXd::Ones(1, m.num_triangles())};
  Field b{"b", Field::Kind::Element, Eigen::MatrixXd::Zero(1, m.num_triangles())};
  const test::TempDir dir;
  const std::string path = dir / "provenance.msh";
  const auto views = gmsh_adapter::add_views({a, b}, tags);
  gmsh_adapter::write_msh(path, views, "homesh x -m y");
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(text.find("$HomeshProvenance\nhomesh x -m y\n$EndHomeshProvenance") != std::string::npos);
  REQUIRE(text.find("$MeshFormat\n4.1") == 0);
  std::ifstream opt(path + ".opt");
  std::string options((std::istreambuf_iterator<char>(opt)), std::istreambuf_iterator<char>());
  REQUIRE(options == gmsh_adapter::sidecar_options(views));
  REQUIRE(options.find("homesh_first_view = PostProcessing.NbViews - 2;") != std::string::npos);
  REQUIRE(options.find("View[homesh_first_view + 1].AdaptVisualizationGrid = 1;") !=
          std::string::npos);
  REQUIRE(options.find("View[homesh_first_view + 2]") == std::string::npos);
  REQUIRE(options.find("View[0]") == std::string::npos);
}

TEST_CASE("write_model gives nodes on a CAD curve without a parameter Gmsh's", "[gmsh]") {
  test::GmshSession session;
  test::make_plate_with_hole(1);
  Mesh m = gmsh_adapter::read_model("plate");
  // Forget the parameter of every other node on a curve, as a stage that adds
  // nodes along a boundary curve leaves them.
  std::map<int, std::vector<std::pair<int, double>>> known;  // curve -> (node, u)
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_class[i].dim == 1) {
      known[m.node_class[i].tag].push_back({i, m.node_class[i].u});
      if (i % 2 == 0) m.node_class[i].u = std::numeric_limits<double>::quiet_NaN();
    }
  REQUIRE(known.size() >= 4);
  gmsh_adapter::write_model(m);
  for (const auto& [curve, nodes] : known) {
    std::vector<std::size_t> tags;
    std::vector<double> coord, param;
    gmsh::model::mesh::getNodes(tags, coord, param, 1, curve, false, true);
    REQUIRE(param.size() == tags.size());  // every node of the curve has its parameter
    REQUIRE(tags.size() == nodes.size());
    for (std::size_t k = 0; k < tags.size(); ++k)
      CHECK(param[k] == Approx(nodes[k].second).margin(1e-9));
  }
}

namespace {

// Two unit squares side by side: quadrilaterals on the left (surface 1),
// triangles on the right (surface 2), order p.
void make_quads_beside_triangles(int p) {
  gmsh::model::add("two");
  const int left = gmsh::model::occ::addRectangle(0, 0, 0, 1, 1);
  const int right = gmsh::model::occ::addRectangle(1, 0, 0, 1, 1);
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  gmsh::model::occ::fragment({{2, left}}, {{2, right}}, out, map);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.25);
  gmsh::model::mesh::setRecombine(2, 1);
  gmsh::model::mesh::generate(2);
  if (p > 1) gmsh::model::mesh::setOrder(p);
}

// The current model (order p, with quadrilaterals) -> core -> model -> .msh
// -> model keeps every element and its node order, a view of each element's
// node indices comes back on the right elements, and the 2D element tags
// increase in the order the file lists the elements (entity by entity): the
// order meshio pairs element data with elements.
void check_quad_round_trip(int p) {
  const int quad_type = gmsh::model::mesh::getElementType("Quadrangle", p);
  std::vector<std::size_t> quad_tags, quad_nodes;
  gmsh::model::mesh::getElementsByType(quad_type, quad_tags, quad_nodes);
  REQUIRE(quad_tags.size() > 10);

  const Mesh m1 = gmsh_adapter::read_model("model");
  REQUIRE(static_cast<std::size_t>(m1.num_quads()) == quad_tags.size());
  REQUIRE(m1.num_triangles() > 10);
  REQUIRE(static_cast<std::size_t>(m1.num_elements_2d()) == gmsh_count(2));
  REQUIRE(m1.quad.rows() == (p + 1) * (p + 1));
  // Gmsh's node order is the reference order: a quadrilateral with straight
  // sides has its nodes at the bilinear map of its corners at quad_reference_nodes.
  const Eigen::Matrix2Xd ref = quad_reference_nodes(p);
  int straight = 0;
  for (int e = 0; e < m1.num_quads(); ++e) {
    const Eigen::Matrix2Xd X = m1.quad_nodes(e);
    double gap = 0;
    for (Eigen::Index k = 0; k < X.cols(); ++k) {
      const double u = ref(0, k), v = ref(1, k);
      const Eigen::Vector2d bilinear = (1 - u) * (1 - v) * X.col(0) + u * (1 - v) * X.col(1) +
                                       u * v * X.col(2) + (1 - u) * v * X.col(3);
      gap = std::max(gap, (X.col(k) - bilinear).norm());
    }
    straight += gap < 1e-12 ? 1 : 0;
  }
  CHECK(straight > m1.num_quads() / 3);

  const auto tags = gmsh_adapter::write_model(m1);
  REQUIRE(tags.element.size() == static_cast<std::size_t>(m1.num_elements_2d()));
  require_same(m1, gmsh_adapter::read_model("model"));
  // A view of each element's node indices over triangles and quadrilaterals.
  Eigen::MatrixXd index = Eigen::MatrixXd::Constant(m1.quad.rows(), m1.num_elements_2d(), -1);
  index.topLeftCorner(m1.tri.rows(), m1.num_triangles()) = m1.tri.cast<double>();
  index.rightCols(m1.num_quads()) = m1.quad.cast<double>();
  const auto views =
      gmsh_adapter::add_views({{"node index", Field::Kind::ElementNode, index}}, tags);
  const test::TempDir dir;
  const std::string path = dir / "quads.msh";
  gmsh_adapter::write_msh(path, views, "test provenance");

  gmsh::clear();
  gmsh::open(path);
  std::vector<std::size_t> element_tags;
  const Mesh m3 = gmsh_adapter::read_model(path, &element_tags);
  require_same(m1, m3, 1e-15);
  REQUIRE(element_tags == tags.element);
  std::vector<std::size_t> file_order;
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::sort(surfaces.begin(), surfaces.end());
  for (const auto& [dim, tag] : surfaces) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> etags, enodes;
    gmsh::model::mesh::getElements(types, etags, enodes, dim, tag);
    for (const auto& t : etags) file_order.insert(file_order.end(), t.begin(), t.end());
  }
  REQUIRE(std::is_sorted(file_order.begin(), file_order.end()));
  std::map<std::size_t, Eigen::Index> element_of;
  for (std::size_t e = 0; e < tags.element.size(); ++e)
    element_of[tags.element[e]] = static_cast<Eigen::Index>(e);
  std::vector<int> view_tags;
  gmsh::view::getTags(view_tags);
  REQUIRE(view_tags.size() == 1);
  std::string type;
  std::vector<std::vector<double>> data;
  double time;
  int components;
  gmsh::view::getModelData(view_tags[0], 0, type, element_tags, data, time, components);
  REQUIRE(element_tags.size() == static_cast<std::size_t>(m1.num_elements_2d()));
  for (std::size_t k = 0; k < element_tags.size(); ++k) {
    const Eigen::Index e = element_of.at(element_tags[k]);
    const bool quad = e >= m1.num_triangles();
    REQUIRE(data[k].size() == static_cast<std::size_t>(quad ? m1.quad.rows() : m1.tri.rows()));
    for (std::size_t i = 0; i < data[k].size(); ++i) REQUIRE(data[k][i] == index(i, e));
  }
}

}  // namespace

TEST_CASE("quadrilaterals mixed with triangles survive model -> core -> .msh -> model, p = 1..4",
          "[gmsh][quads]") {
  for (int p = 1; p <= 4; ++p) {
    CAPTURE(p);
    {
      INFO("a boundary layer of quadrilaterals in a triangle mesh");
      test::GmshSession session;
      test::make_plate_with_quad_layer(p);
      check_quad_round_trip(p);
    }
    {
      INFO("quadrilaterals on one surface, triangles on the next");
      test::GmshSession session;
      make_quads_beside_triangles(p);
      check_quad_round_trip(p);
    }
  }
}

TEST_CASE("incomplete quadrilaterals are refused naming their type", "[gmsh][quads]") {
  test::GmshSession session;
  test::make_plate_with_quad_layer(1, 0.3, true);
  gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 1);
  gmsh::model::mesh::setOrder(2);
  REQUIRE_THROWS_WITH(gmsh_adapter::read_model("plate"),
                      Catch::Contains("type 'Quadrilateral 8' (Gmsh type 16)") &&
                          Catch::Contains("incomplete (serendipity)"));
}
