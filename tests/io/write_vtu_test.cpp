#include "io/write_vtu.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../support/temp_dir.h"
#include "core/error.h"

using namespace homesh;

namespace {

// The unit square as two quadratic triangles (0 1 2) and (0 2 3) and its four
// boundary lines, on surface 1 and curves 1..4. Physical groups: surface 5 =
// {1}; curves 7 = {1, 2} and 3 = {2}, so curve 2 is in two groups and curves
// 3 and 4 in none.
Mesh square(int p) {
  Mesh m;
  m.order = p;
  m.x.resize(2, p == 1 ? 4 : 9);
  m.x.leftCols(4) << 0, 1, 1, 0, 0, 0, 1, 1;
  if (p == 2) {
    m.x.rightCols(5) << 0.5, 1, 0.5, 0.5, 0, 0, 0.5, 0.5, 1, 0.5;
    m.tri.resize(6, 2);
    m.tri << 0, 0, 1, 2, 2, 3, 4, 6, 5, 7, 6, 8;
    m.line.resize(3, 4);
    m.line << 0, 1, 2, 3, 1, 2, 3, 0, 4, 5, 7, 8;
  } else {
    m.tri.resize(3, 2);
    m.tri << 0, 0, 1, 2, 2, 3;
    m.line.resize(2, 4);
    m.line << 0, 1, 2, 3, 1, 2, 3, 0;
  }
  m.node_class.resize(static_cast<std::size_t>(m.num_nodes()));
  m.tri_entity = {1, 1};
  m.line_entity = {1, 2, 3, 4};
  m.physicals = {{2, 5, "domain", {1}}, {1, 7, "walls", {1, 2}}, {1, 3, "right", {2}}};
  return m;
}

std::string decoded(const std::string& text) {
  std::string out;
  std::uint32_t bits = 0;
  int count = 0;
  for (char c : text) {
    const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    if (c == '=') break;
    bits = (bits << 6) | static_cast<std::uint32_t>(std::strchr(digits, c) - digits);
    if ((count += 6) >= 8) out += static_cast<char>((bits >> (count -= 8)) & 0xffu);
  }
  return out;
}

// The values of the DataArray `name` of `vtu`, after checking its byte-count header.
template <typename T>
std::vector<T> array(const std::string& vtu, const std::string& name) {
  std::smatch m;
  REQUIRE(std::regex_search(
      vtu, m, std::regex("Name=\"" + name + "\"[^>]*format=\"binary\">([A-Za-z0-9+/=]*)<")));
  const std::string bytes = decoded(m[1]);
  REQUIRE(bytes.size() >= 8);
  std::uint64_t size = 0;
  std::memcpy(&size, bytes.data(), 8);
  REQUIRE(size == bytes.size() - 8);
  REQUIRE(size % sizeof(T) == 0);
  std::vector<T> values(size / sizeof(T));
  std::memcpy(values.data(), bytes.data() + 8, size);
  return values;
}

std::vector<Field> fields() {
  Eigen::MatrixXd q4(6, 2);
  q4 << 1, 10, 2, 11, 3, 12, 4, 13, 5, 14, 6, 15;
  return {{"minJ/maxJ", Field::Kind::Element, Eigen::RowVector2d(0.9, 0.8)},
          {"Q4", Field::Kind::ElementNode, q4}};
}

}  // namespace

TEST_CASE("vtu_text writes Lagrange cells, the Gmsh tags and the groups as cell data",
          "[io][write_vtu]") {
  const Mesh m = square(2);
  const std::string vtu = vtu_text(m, fields(), "homesh test");
  CHECK_THAT(vtu, Catch::Contains("NumberOfPoints=\"9\" NumberOfCells=\"6\""));
  // Lagrange triangles, then the lines as poly-lines (VTK crashes on Lagrange curves).
  CHECK(array<std::uint8_t>(vtu, "types") == std::vector<std::uint8_t>{69, 69, 4, 4, 4, 4});
  CHECK(array<std::int64_t>(vtu, "offsets") == std::vector<std::int64_t>{6, 12, 15, 18, 21, 24});
  CHECK(
      array<std::int64_t>(vtu, "connectivity") ==
      std::vector<std::int64_t>{0, 1, 2, 4, 5, 6, 0, 2, 3, 6, 7, 8,  // triangles, VTK = Gmsh order
                                0, 4, 1, 1, 5, 2, 2, 7, 3, 3, 8, 0});  // lines, along each
  const auto points = array<double>(vtu, "Points");
  REQUIRE(points.size() == 27);
  for (int i = 0; i < 9; ++i) {
    CHECK(points[3 * i] == m.x(0, i));
    CHECK(points[3 * i + 1] == m.x(1, i));
    CHECK(points[3 * i + 2] == 0.0);
  }
  // Gmsh tags as homesh writes the .msh: the 4 lines 1..4, then the triangles 5, 6.
  CHECK(array<std::int64_t>(vtu, "gmsh:element") == std::vector<std::int64_t>{5, 6, 1, 2, 3, 4});
  CHECK(array<std::int32_t>(vtu, "gmsh:geometrical") ==
        std::vector<std::int32_t>{1, 1, 1, 2, 3, 4});
  CHECK(array<std::int32_t>(vtu, "gmsh:physical") == std::vector<std::int32_t>{5, 5, 7, 3, 0, 0});
  CHECK_THAT(vtu, Catch::Contains("<!--\nhomesh test\n-->"));
}

TEST_CASE("vtu_text writes element fields as cell data, NaN on the lines", "[io][write_vtu]") {
  const std::string vtu = vtu_text(square(2), fields(), "");
  const auto ratio = array<double>(vtu, "minJ/maxJ");
  REQUIRE(ratio.size() == 6);
  CHECK(ratio[0] == 0.9);
  CHECK(ratio[1] == 0.8);
  for (int l = 2; l < 6; ++l) CHECK(std::isnan(ratio[static_cast<std::size_t>(l)]));
}

TEST_CASE(
    "vtu_text writes element-node fields per element as cell data and their minimum "
    "at each point as point data",
    "[io][write_vtu]") {
  const std::string vtu = vtu_text(square(2), fields(), "");
  CHECK_THAT(vtu, Catch::Contains("Name=\"Q4\" NumberOfComponents=\"6\""));
  const auto at_nodes = array<double>(vtu, "Q4");
  REQUIRE(at_nodes.size() == 36);
  for (int k = 0; k < 6; ++k) {
    CHECK(at_nodes[static_cast<std::size_t>(k)] == k + 1);
    CHECK(at_nodes[static_cast<std::size_t>(6 + k)] == k + 10);
  }
  for (std::size_t k = 12; k < 36; ++k) CHECK(std::isnan(at_nodes[k]));
  // Nodes 0, 2 and 6 (the diagonal) are shared: the smaller of the two triangles' values.
  CHECK(array<double>(vtu, "Q4, smallest at the point") ==
        std::vector<double>{1, 2, 3, 12, 4, 5, 6, 14, 15});
}

TEST_CASE("vtu_text writes a field of a few elements with NaN on the others", "[io][write_vtu]") {
  Field poor{"poor", Field::Kind::ElementNode, Eigen::MatrixXd::Constant(6, 1, 0.3)};
  poor.elements = {1};
  const std::string vtu = vtu_text(square(2), {poor}, "");
  const auto cells = array<double>(vtu, "poor");
  REQUIRE(cells.size() == 36);
  for (std::size_t k = 0; k < 36; ++k) CHECK((k >= 6 && k < 12) == !std::isnan(cells[k]));
  for (std::size_t k = 6; k < 12; ++k) CHECK(cells[k] == 0.3);
  const Field none{"none", Field::Kind::ElementNode, Eigen::MatrixXd(6, 0)};
  CHECK_THAT(vtu_text(square(2), {none}, ""), !Catch::Contains("Name=\"none\""));
  poor.elements = {2};
  REQUIRE_THROWS_WITH(vtu_text(square(2), {poor}, ""), "vtu: field 'poor' lists element 2 of 2");
}

TEST_CASE("vtu_text writes order 1 as VTK's linear cells", "[io][write_vtu]") {
  const std::string vtu = vtu_text(square(1), {}, "");
  CHECK(array<std::uint8_t>(vtu, "types") == std::vector<std::uint8_t>{5, 5, 3, 3, 3, 3});
  CHECK(array<std::int64_t>(vtu, "offsets") == std::vector<std::int64_t>{3, 6, 8, 10, 12, 14});
}

TEST_CASE("vtu_text keeps the provenance comment and the names well-formed XML",
          "[io][write_vtu]") {
  Field odd{"a<b & \"c\"", Field::Kind::Element, Eigen::RowVector2d(1, 2)};
  const std::string vtu = vtu_text(square(2), {odd}, "homesh in.geo --keep-invalid out.vtu-");
  const auto open = vtu.find("<!--"), close = vtu.find("-->");
  REQUIRE(close != std::string::npos);
  const std::string comment = vtu.substr(open + 4, close - open - 4);
  CHECK_THAT(comment, Catch::Contains("keep-invalid"));
  CHECK(comment.find("--") == std::string::npos);
  CHECK(comment.back() != '-');
  CHECK_THAT(vtu, Catch::Contains("Name=\"a&lt;b &amp; &quot;c&quot;\""));
}

TEST_CASE("vtu_text refuses a field that does not fit the mesh", "[io][write_vtu]") {
  const Field wrong{"Q4", Field::Kind::ElementNode, Eigen::MatrixXd::Zero(3, 2)};
  CHECK_THROWS_WITH(vtu_text(square(2), {wrong}, ""),
                    "vtu: field 'Q4' is 3 by 2, but the mesh has 2 elements of 6 nodes each");
}

TEST_CASE("write_vtu writes the text atomically, an error naming the path", "[io][write_vtu]") {
  const homesh::test::TempDir dir;
  const Mesh m = square(2);
  write_vtu(dir / "out.vtu", m, fields(), "p");
  std::ifstream in(dir / "out.vtu");
  std::stringstream text;
  text << in.rdbuf();
  CHECK(text.str() == vtu_text(m, fields(), "p"));
  CHECK_THROWS_WITH(write_vtu(dir / "missing/out.vtu", m, fields(), "p"),
                    Catch::StartsWith("cannot write '" + dir / "missing/out.vtu" + "'"));
  const Field wrong{"Q4", Field::Kind::Element, Eigen::MatrixXd::Zero(1, 3)};
  CHECK_THROWS_WITH(write_vtu(dir / "out.vtu", m, {wrong}, "p"),
                    Catch::StartsWith(dir / "out.vtu: vtu: field 'Q4'"));
  std::ifstream again(dir / "out.vtu");
  std::stringstream kept;
  kept << again.rdbuf();
  CHECK(kept.str() == text.str());
}

TEST_CASE("vtu_text writes quadrilaterals as Lagrange quadrilaterals beside the triangles",
          "[io][write_vtu]") {
  // A quadratic unit square (nodes 0..8, Gmsh order) and a quadratic triangle
  // on its top edge (nodes 3, 2, 9; edge nodes 6, 10, 11), one line below.
  Mesh m;
  m.order = 2;
  m.x.resize(2, 12);
  m.x << 0, 1, 1, 0, 0.5, 1, 0.5, 0, 0.5, 0.5, 0.75, 0.25,  //
      0, 0, 1, 1, 0, 0.5, 1, 0.5, 0.5, 2, 1.5, 1.5;
  m.node_class.resize(12);
  m.quad.resize(9, 1);
  m.quad << 0, 1, 2, 3, 4, 5, 6, 7, 8;
  m.quad_entity = {1};
  m.tri.resize(6, 1);
  m.tri << 3, 2, 9, 6, 10, 11;
  m.tri_entity = {1};
  m.line.resize(3, 1);
  m.line << 0, 1, 4;
  m.line_entity = {1};
  Eigen::MatrixXd at_nodes =
      Eigen::MatrixXd::Constant(9, 2, std::numeric_limits<double>::quiet_NaN());
  at_nodes.col(0).head(6) << 1, 2, 3, 4, 5, 6;
  at_nodes.col(1) << 10, 11, 12, 13, 14, 15, 16, 17, 18;
  const std::string vtu =
      vtu_text(m,
               {{"minJ/maxJ", Field::Kind::Element, Eigen::RowVector2d(0.9, 0.8)},
                {"Q4", Field::Kind::ElementNode, at_nodes}},
               "");
  CHECK(array<std::uint8_t>(vtu, "types") == std::vector<std::uint8_t>{69, 70, 4});
  // VTK's quadrilateral: corners, edges 0-1, 1-2, then 3-2 and 0-3 (increasing), centre.
  CHECK(array<std::int64_t>(vtu, "connectivity") ==
        std::vector<std::int64_t>{3, 2, 9, 6, 10, 11, 0, 1, 2, 3, 4, 5, 6, 7, 8, 0, 4, 1});
  // Tags: the line, the triangle, then the quadrilateral (one surface).
  CHECK(array<std::int64_t>(vtu, "gmsh:element") == std::vector<std::int64_t>{2, 3, 1});
  CHECK(array<double>(vtu, "minJ/maxJ")[1] == 0.8);
  const auto q4 = array<double>(vtu, "Q4");
  REQUIRE(q4.size() == 27);  // 9 components per cell
  CHECK(q4[0] == 1);
  CHECK(std::isnan(q4[6]));  // a triangle's components beyond its 6 nodes
  CHECK(q4[9] == 10);
  CHECK(q4[17] == 18);
  // At node 2, shared by both: the smaller of the triangle's 2 and the quad's 12.
  CHECK(array<double>(vtu, point_field_name("Q4"))[2] == 2);
}
