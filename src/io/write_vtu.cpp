#include "io/write_vtu.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <map>

#include "core/atomic_file.h"
#include "core/error.h"
#include "io/vtk_node_order.h"

namespace homesh {
namespace {

constexpr std::uint8_t kVtkLine = 3, kVtkPolyLine = 4, kVtkTriangle = 5, kVtkQuad = 9,
                       kVtkTetra = 10, kVtkLagrangeTriangle = 69, kVtkLagrangeQuadrilateral = 70,
                       kVtkLagrangeTetrahedron = 71;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Appends `value`'s bytes to `bytes`, least significant first.
template <typename T>
void put(std::string& bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
  for (std::size_t i = sizeof(T); i-- > 0;) bytes += raw[i];
#else
  bytes.append(raw, sizeof(T));
#endif
}

std::string base64(const std::string& in) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < in.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, in.size() - i);
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 3; ++k)
      v = (v << 8) | (k < n ? static_cast<unsigned char>(in[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? digits[(v >> (18 - 6 * k)) & 63u] : '=';
  }
  return out;
}

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// An XML comment holding `text`: "--" may not occur inside one, nor may it end in "-".
std::string xml_comment(std::string text) {
  for (auto at = text.find("--"); at != std::string::npos; at = text.find("--", at))
    text.insert(at + 1, " ");
  return "<!--\n" + text + "\n-->\n";
}

// One inline binary DataArray: base64 of the UInt64 byte count, then the bytes.
std::string data_array(const std::string& type, const std::string& name, int components,
                       const std::string& bytes) {
  std::string block;
  put<std::uint64_t>(block, bytes.size());
  block += bytes;
  return "        <DataArray type=\"" + type + "\" Name=\"" + xml_escaped(name) +
         "\" NumberOfComponents=\"" + std::to_string(components) + "\" format=\"binary\">" +
         base64(block) + "</DataArray>\n";
}

// The field's values over `n` elements of `rows` values each: a field of a
// few elements (Field::elements) gets NaN on the others.
Eigen::MatrixXd all_elements(const Field& f, int n, Eigen::Index node_rows) {
  const Eigen::Index rows = f.kind == Field::Kind::Element ? 1 : node_rows;
  const Eigen::Index cols = f.elements.empty() ? n : static_cast<Eigen::Index>(f.elements.size());
  if (f.values.rows() != rows || f.values.cols() != cols)
    throw Error("vtu: field '" + f.name + "' is " + std::to_string(f.values.rows()) + " by " +
                std::to_string(f.values.cols()) + ", but the mesh has " +
                std::to_string(f.elements.empty() ? n : f.elements.size()) +
                (f.elements.empty() ? " elements" : " listed elements") + " of " +
                std::to_string(rows) + (rows == 1 ? " value" : " nodes") + " each");
  if (f.elements.empty()) return f.values;
  Eigen::MatrixXd out = Eigen::MatrixXd::Constant(rows, n, kNaN);
  for (std::size_t k = 0; k < f.elements.size(); ++k) {
    const int e = f.elements[k];
    if (e < 0 || e >= n)
      throw Error("vtu: field '" + f.name + "' lists element " + std::to_string(e) + " of " +
                  std::to_string(n));
    out.col(e) = f.values.col(static_cast<Eigen::Index>(k));
  }
  return out;
}

// The smallest physical group tag of dimension `dim` holding each entity of that dimension.
std::map<int, int> physical_of(const std::vector<PhysicalGroup>& physicals, int dim) {
  std::map<int, int> out;
  for (const PhysicalGroup& g : physicals) {
    if (g.dim != dim) continue;
    for (int e : g.entities) {
      auto [it, added] = out.emplace(e, g.tag);
      if (!added) it->second = std::min(it->second, g.tag);
    }
  }
  return out;
}

// Cells of one kind: their Gmsh nodes (columns of conn), the Gmsh node of
// each VTK node (map), the VTK type, entity (of dimension dim) and Gmsh tag of
// each. The blocks fields cover come first, numbered on from 0 in order.
struct CellBlock {
  const Eigen::MatrixXi* conn;
  std::vector<int> map;
  std::uint8_t type;
  const std::vector<int>* entity;
  int dim;
  std::function<std::int64_t(int)> tag;
  bool fields;
};

// The .vtu text of `points` and `blocks`, with `fields` over the cells of the
// blocks that take fields (node_rows values per element for ElementNode fields).
std::string unstructured_grid(const Eigen::Matrix3Xd& points, const std::vector<CellBlock>& blocks,
                              const std::vector<Field>& fields, Eigen::Index node_rows,
                              const std::vector<PhysicalGroup>& physicals,
                              const std::string& provenance) {
  int field_cells = 0, cells = 0;
  for (const CellBlock& b : blocks) {
    cells += static_cast<int>(b.conn->cols());
    if (b.fields) field_cells += static_cast<int>(b.conn->cols());
  }
  // A field of no element (no poor triangles, say) is left out, as in the .msh.
  std::vector<const Field*> written;
  std::vector<Eigen::MatrixXd> values_of;
  for (const Field& f : fields)
    if (f.values.cols() > 0 || field_cells == 0) {
      written.push_back(&f);
      values_of.push_back(all_elements(f, field_cells, node_rows));
    }

  std::string xyz, connectivity, offsets, types, element, geometrical, physical;
  for (Eigen::Index i = 0; i < points.cols(); ++i)
    for (int d = 0; d < 3; ++d) put(xyz, points(d, i));
  std::int64_t end = 0;
  std::map<int, std::map<int, int>> groups;  // by dimension
  for (const CellBlock& b : blocks) {
    if (!groups.count(b.dim)) groups[b.dim] = physical_of(physicals, b.dim);
    const std::map<int, int>& group = groups[b.dim];
    for (Eigen::Index e = 0; e < b.conn->cols(); ++e) {
      for (int g : b.map) put<std::int64_t>(connectivity, (*b.conn)(g, e));
      put(offsets, end += static_cast<std::int64_t>(b.map.size()));
      put(types, b.type);
      const int entity = (*b.entity)[static_cast<std::size_t>(e)];
      put(element, b.tag(static_cast<int>(e)));
      put<std::int32_t>(geometrical, entity);
      const auto it = group.find(entity);
      put<std::int32_t>(physical, it == group.end() ? 0 : it->second);
    }
  }

  std::string cell_data = data_array("Int64", "gmsh:element", 1, element) +
                          data_array("Int32", "gmsh:geometrical", 1, geometrical) +
                          data_array("Int32", "gmsh:physical", 1, physical);
  std::string point_data;
  for (std::size_t i = 0; i < written.size(); ++i) {
    const Field& f = *written[i];
    const Eigen::MatrixXd& v = values_of[i];
    std::string values;
    const auto components = static_cast<std::size_t>(v.rows());
    const bool element_field = f.kind == Field::Kind::Element;
    std::vector<double> at_point(static_cast<std::size_t>(points.cols()), kNaN);
    int e = 0;
    for (const CellBlock& b : blocks) {
      if (!b.fields) {
        for (std::size_t k = 0; k < b.conn->cols() * components; ++k) put(values, kNaN);
        continue;
      }
      for (Eigen::Index c = 0; c < b.conn->cols(); ++c, ++e) {
        const std::vector<int> order = element_field ? std::vector<int>{0} : b.map;
        for (int k : order) put(values, v(k, e));
        for (auto k = order.size(); k < components; ++k) put(values, kNaN);
        if (element_field) continue;
        for (std::size_t k = 0; k < b.map.size(); ++k) {
          double& x =
              at_point[static_cast<std::size_t>((*b.conn)(static_cast<Eigen::Index>(k), c))];
          x = std::fmin(x, v(static_cast<Eigen::Index>(k), e));
        }
      }
    }
    cell_data += data_array("Float64", f.name, static_cast<int>(components), values);
    if (!element_field) {
      std::string bytes;
      for (double x : at_point) put(bytes, x);
      point_data += data_array("Float64", point_field_name(f.name), 1, bytes);
    }
  }

  std::string out = "<?xml version=\"1.0\"?>\n" + xml_comment(provenance);
  out += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" ";
  out += "header_type=\"UInt64\">\n  <UnstructuredGrid>\n";
  out += "    <Piece NumberOfPoints=\"" + std::to_string(points.cols()) + "\" NumberOfCells=\"" +
         std::to_string(cells) + "\">\n";
  out += "      <Points>\n" + data_array("Float64", "Points", 3, xyz) + "      </Points>\n";
  out += "      <Cells>\n" + data_array("Int64", "connectivity", 1, connectivity) +
         data_array("Int64", "offsets", 1, offsets) + data_array("UInt8", "types", 1, types) +
         "      </Cells>\n";
  out += "      <CellData>\n" + cell_data + "      </CellData>\n";
  out += "      <PointData>\n" + point_data + "      </PointData>\n";
  out += "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

// Writes `text` to `path` atomically, an Error making it naming `path`.
template <class Text>
void write_text(const std::string& path, Text text_of) {
  std::string text;
  try {
    text = text_of();
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
  write_file_atomically(path, text);
}

}  // namespace

std::string vtu_text(const Mesh& mesh, const std::vector<Field>& fields,
                     const std::string& provenance, const ElementTags& tags) {
  if (!tags.triangles.empty() &&
      tags.triangles.size() != static_cast<std::size_t>(mesh.num_elements_2d()))
    throw Error("vtu: " + std::to_string(tags.triangles.size()) + " element tags for " +
                std::to_string(mesh.num_elements_2d()) + " elements");
  if (!tags.lines.empty() && tags.lines.size() != static_cast<std::size_t>(mesh.num_lines()))
    throw Error("vtu: " + std::to_string(tags.lines.size()) + " line tags for " +
                std::to_string(mesh.num_lines()) + " lines");
  const int p = mesh.order, triangles = mesh.num_triangles();
  Eigen::Matrix3Xd points = Eigen::Matrix3Xd::Zero(3, mesh.num_nodes());
  points.topRows<2>() = mesh.x;
  const auto first_line_tag = static_cast<std::int64_t>(1 + mesh.point_node.size());
  const std::vector<CellBlock> blocks = {
      {&mesh.tri, gmsh_to_vtk_triangle(p), p == 1 ? kVtkTriangle : kVtkLagrangeTriangle,
       &mesh.tri_entity, 2,
       [&](int e) {
         return static_cast<std::int64_t>(tags.triangles.empty() ? mesh.triangle_tag(e)
                                                                 : tags.triangles[e]);
       },
       true},
      {&mesh.quad, gmsh_to_vtk_quad(p), p == 1 ? kVtkQuad : kVtkLagrangeQuadrilateral,
       &mesh.quad_entity, 2,
       [&](int q) {
         return static_cast<std::int64_t>(tags.triangles.empty() ? mesh.quad_tag(q)
                                                                 : tags.triangles[triangles + q]);
       },
       true},
      {&mesh.line, line_nodes_along(p), p == 1 ? kVtkLine : kVtkPolyLine, &mesh.line_entity, 1,
       [&](int l) {
         return tags.lines.empty() ? first_line_tag + l : static_cast<std::int64_t>(tags.lines[l]);
       },
       false}};
  const Eigen::Index rows =
      mesh.num_quads() > 0 ? quad_node_count(mesh.order) : triangle_node_count(mesh.order);
  return unstructured_grid(points, blocks, fields, rows, mesh.physicals, provenance);
}

std::string vtu_text(const VolumeMesh& mesh, const std::vector<Field>& fields,
                     const std::string& provenance, const std::vector<std::size_t>& tet_tags) {
  if (!tet_tags.empty() && tet_tags.size() != static_cast<std::size_t>(mesh.num_tetrahedra()))
    throw Error("vtu: " + std::to_string(tet_tags.size()) + " tetrahedron tags for " +
                std::to_string(mesh.num_tetrahedra()) + " tetrahedra");
  const int p = mesh.order;
  const auto first_line_tag = static_cast<std::int64_t>(1 + mesh.point_node.size());
  const auto first_triangle_tag = first_line_tag + mesh.num_lines();
  const std::vector<CellBlock> blocks = {
      {&mesh.tet, gmsh_to_vtk_tetrahedron(p), p == 1 ? kVtkTetra : kVtkLagrangeTetrahedron,
       &mesh.tet_entity, 3,
       [&](int e) {
         return static_cast<std::int64_t>(tet_tags.empty() ? mesh.tetrahedron_tag(e) : tet_tags[e]);
       },
       true},
      {&mesh.tri, gmsh_to_vtk_triangle(p), p == 1 ? kVtkTriangle : kVtkLagrangeTriangle,
       &mesh.tri_entity, 2, [&](int e) { return first_triangle_tag + e; }, false},
      {&mesh.line, line_nodes_along(p), p == 1 ? kVtkLine : kVtkPolyLine, &mesh.line_entity, 1,
       [&](int l) { return first_line_tag + l; }, false}};
  return unstructured_grid(mesh.x, blocks, fields, tetrahedron_node_count(p), mesh.physicals,
                           provenance);
}

void write_vtu(const std::string& path, const Mesh& mesh, const std::vector<Field>& fields,
               const std::string& provenance, const ElementTags& tags) {
  write_text(path, [&] { return vtu_text(mesh, fields, provenance, tags); });
}

void write_vtu(const std::string& path, const VolumeMesh& mesh, const std::vector<Field>& fields,
               const std::string& provenance, const std::vector<std::size_t>& tet_tags) {
  write_text(path, [&] { return vtu_text(mesh, fields, provenance, tet_tags); });
}

}  // namespace homesh
