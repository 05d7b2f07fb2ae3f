#include "io/write_vtu.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>

#include "core/atomic_file.h"
#include "core/error.h"
#include "io/vtk_node_order.h"

namespace homesh {
namespace {

constexpr std::uint8_t kVtkLine = 3, kVtkPolyLine = 4, kVtkTriangle = 5, kVtkQuad = 9,
                       kVtkLagrangeTriangle = 69, kVtkLagrangeQuadrilateral = 70;
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

// The field's values over every 2D element: a field of a few elements
// (Field::elements) gets NaN on the others.
Eigen::MatrixXd all_elements(const Field& f, const Mesh& m) {
  const int n = m.num_elements_2d();
  const Eigen::Index rows = f.kind == Field::Kind::Element ? 1
                            : m.num_quads() > 0            ? quad_node_count(m.order)
                                                           : triangle_node_count(m.order);
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
std::map<int, int> physical_of(const Mesh& m, int dim) {
  std::map<int, int> out;
  for (const PhysicalGroup& g : m.physicals) {
    if (g.dim != dim) continue;
    for (int e : g.entities) {
      auto [it, added] = out.emplace(e, g.tag);
      if (!added) it->second = std::min(it->second, g.tag);
    }
  }
  return out;
}

}  // namespace

std::string vtu_text(const Mesh& mesh, const std::vector<Field>& fields,
                     const std::string& provenance, const ElementTags& tags) {
  // A field of no element (no poor triangles, say) is left out, as in the .msh.
  std::vector<const Field*> written;
  std::vector<Eigen::MatrixXd> values_of;
  for (const Field& f : fields)
    if (f.values.cols() > 0 || mesh.num_elements_2d() == 0) {
      written.push_back(&f);
      values_of.push_back(all_elements(f, mesh));
    }
  if (!tags.triangles.empty() &&
      tags.triangles.size() != static_cast<std::size_t>(mesh.num_elements_2d()))
    throw Error("vtu: " + std::to_string(tags.triangles.size()) + " element tags for " +
                std::to_string(mesh.num_elements_2d()) + " elements");
  if (!tags.lines.empty() && tags.lines.size() != static_cast<std::size_t>(mesh.num_lines()))
    throw Error("vtu: " + std::to_string(tags.lines.size()) + " line tags for " +
                std::to_string(mesh.num_lines()) + " lines");
  const int p = mesh.order;
  const int triangles = mesh.num_triangles(), quads = mesh.num_quads(), lines = mesh.num_lines();
  const int elements = triangles + quads;
  const std::vector<int> tri_map = gmsh_to_vtk_triangle(p), line_map = line_nodes_along(p);
  const std::vector<int> quad_map = gmsh_to_vtk_quad(p);

  std::string points, connectivity, offsets, types;
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    put(points, mesh.x(0, i));
    put(points, mesh.x(1, i));
    put(points, 0.0);
  }
  std::int64_t end = 0;
  for (int e = 0; e < triangles; ++e) {
    for (int g : tri_map) put<std::int64_t>(connectivity, mesh.tri(g, e));
    put(offsets, end += static_cast<std::int64_t>(tri_map.size()));
    put(types, p == 1 ? kVtkTriangle : kVtkLagrangeTriangle);
  }
  for (int q = 0; q < quads; ++q) {
    for (int g : quad_map) put<std::int64_t>(connectivity, mesh.quad(g, q));
    put(offsets, end += static_cast<std::int64_t>(quad_map.size()));
    put(types, p == 1 ? kVtkQuad : kVtkLagrangeQuadrilateral);
  }
  for (int l = 0; l < lines; ++l) {
    for (int g : line_map) put<std::int64_t>(connectivity, mesh.line(g, l));
    put(offsets, end += static_cast<std::int64_t>(line_map.size()));
    put(types, p == 1 ? kVtkLine : kVtkPolyLine);
  }

  std::string element, geometrical, physical;
  const std::map<int, int> surface_group = physical_of(mesh, 2), curve_group = physical_of(mesh, 1);
  const auto group = [](const std::map<int, int>& groups, int entity) {
    const auto it = groups.find(entity);
    return it == groups.end() ? 0 : it->second;
  };
  const auto first_line_tag = 1 + mesh.point_node.size();
  for (int e = 0; e < elements; ++e) {
    const auto k = static_cast<std::size_t>(e);
    const int entity = e < triangles ? mesh.tri_entity[k] : mesh.quad_entity[k - triangles];
    put(element, static_cast<std::int64_t>(tags.triangles.empty() ? mesh.triangle_tag(e)
                                                                  : tags.triangles[k]));
    put<std::int32_t>(geometrical, entity);
    put<std::int32_t>(physical, group(surface_group, entity));
  }
  for (int l = 0; l < lines; ++l) {
    const auto k = static_cast<std::size_t>(l);
    put(element,
        static_cast<std::int64_t>(tags.lines.empty() ? first_line_tag + k : tags.lines[k]));
    put<std::int32_t>(geometrical, mesh.line_entity[k]);
    put<std::int32_t>(physical, group(curve_group, mesh.line_entity[k]));
  }

  std::string cell_data = data_array("Int64", "gmsh:element", 1, element) +
                          data_array("Int32", "gmsh:geometrical", 1, geometrical) +
                          data_array("Int32", "gmsh:physical", 1, physical);
  std::string point_data;
  for (std::size_t i = 0; i < written.size(); ++i) {
    const Field& f = *written[i];
    const Eigen::MatrixXd& v = values_of[i];
    std::string values;
    const auto components = static_cast<int>(v.rows());
    const bool element_field = f.kind == Field::Kind::Element;
    const std::vector<int> tri_order = element_field ? std::vector<int>{0} : tri_map;
    const std::vector<int> quad_order = element_field ? std::vector<int>{0} : quad_map;
    for (int e = 0; e < elements; ++e) {
      const std::vector<int>& order = e < triangles ? tri_order : quad_order;
      for (int k : order) put(values, v(k, e));
      for (auto k = order.size(); k < static_cast<std::size_t>(components); ++k) put(values, kNaN);
    }
    for (int l = 0; l < lines * components; ++l) put(values, kNaN);
    cell_data += data_array("Float64", f.name, components, values);
    if (!element_field) {
      std::vector<double> at_point(static_cast<std::size_t>(mesh.num_nodes()), kNaN);
      for (int e = 0; e < elements; ++e) {
        const bool quad = e >= triangles;
        const int nodes = static_cast<int>(quad ? quad_map.size() : tri_map.size());
        for (int k = 0; k < nodes; ++k) {
          const int node = quad ? mesh.quad(k, e - triangles) : mesh.tri(k, e);
          double& x = at_point[static_cast<std::size_t>(node)];
          x = std::fmin(x, v(k, e));
        }
      }
      std::string bytes;
      for (double x : at_point) put(bytes, x);
      point_data += data_array("Float64", point_field_name(f.name), 1, bytes);
    }
  }

  std::string out = "<?xml version=\"1.0\"?>\n" + xml_comment(provenance);
  out += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" ";
  out += "header_type=\"UInt64\">\n  <UnstructuredGrid>\n";
  out += "    <Piece NumberOfPoints=\"" + std::to_string(mesh.num_nodes()) + "\" NumberOfCells=\"" +
         std::to_string(elements + lines) + "\">\n";
  out += "      <Points>\n" + data_array("Float64", "Points", 3, points) + "      </Points>\n";
  out += "      <Cells>\n" + data_array("Int64", "connectivity", 1, connectivity) +
         data_array("Int64", "offsets", 1, offsets) + data_array("UInt8", "types", 1, types) +
         "      </Cells>\n";
  out += "      <CellData>\n" + cell_data + "      </CellData>\n";
  out += "      <PointData>\n" + point_data + "      </PointData>\n";
  out += "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

void write_vtu(const std::string& path, const Mesh& mesh, const std::vector<Field>& fields,
               const std::string& provenance, const ElementTags& tags) {
  std::string text;
  try {
    text = vtu_text(mesh, fields, provenance, tags);
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
  write_file_atomically(path, text);
}

}  // namespace homesh
