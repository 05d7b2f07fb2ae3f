#include "core/check_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <sstream>
#include <unordered_map>

#include "core/error.h"
#include "core/input_limits.h"

namespace homesh {
namespace {

std::string where(const Mesh& m, int e) {
  const Eigen::Vector2d c = m.corner_centroid(e);
  std::ostringstream s;
  s << "triangle " << e + 1 << " at (" << c.x() << ", " << c.y() << ")";
  return s.str();
}

std::string where_quad(const Mesh& m, int e) {
  const Eigen::Vector2d c = m.corner_centroid(m.num_triangles() + e);
  std::ostringstream s;
  s << "quadrilateral " << e + 1 << " at (" << c.x() << ", " << c.y() << ")";
  return s.str();
}

std::string fmt_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Every corner edge bounds one or two elements (triangles or quadrilaterals):
// a third one sharing it makes the mesh non-manifold, which no stage can curve
// or layer.
void check_manifold(const Mesh& m, const std::string& source) {
  std::unordered_map<std::uint64_t, int> uses;
  uses.reserve(static_cast<std::size_t>(3 * m.num_triangles() + 4 * m.num_quads()));
  // The element is named only when it is at fault: formatting its place for every
  // edge cost a tenth of a layers stage at 1e6 triangles.
  const auto use = [&](int i, int j, int e, bool quad) {
    const auto a = static_cast<std::uint32_t>(i), b = static_cast<std::uint32_t>(j);
    const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
    if (++uses[key] > 2)
      throw Error(source + ": the edge between nodes " + std::to_string(std::min(a, b) + 1) +
                  " and " + std::to_string(std::max(a, b) + 1) + " of " +
                  (quad ? where_quad(m, e) : where(m, e)) +
                  " is shared by three or more elements (a non-manifold mesh)");
  };
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int k = 0; k < 3; ++k) use(m.tri(k, e), m.tri((k + 1) % 3, e), e, false);
  for (int e = 0; e < m.num_quads(); ++e)
    for (int k = 0; k < 4; ++k) use(m.quad(k, e), m.quad((k + 1) % 4, e), e, true);
}

// A quadrilateral's corners: distinct, counter-clockwise (Gmsh's order), of
// non-zero area, and not those of another quadrilateral.
void check_quads(const Mesh& m, const std::string& source) {
  std::set<std::array<int, 4>> seen;
  for (int e = 0; e < m.num_quads(); ++e) {
    std::array<int, 4> c = {m.quad(0, e), m.quad(1, e), m.quad(2, e), m.quad(3, e)};
    double area2 = 0, scale = 0;
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector2d a = m.x.col(c[k]), b = m.x.col(c[(k + 1) % 4]);
      area2 += a.x() * b.y() - a.y() * b.x();
      scale = std::max(scale, (b - a).squaredNorm());
    }
    std::array<int, 4> sorted = c;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw Error(source + ": " + where_quad(m, e) + " repeats a corner node");
    if (std::abs(area2) <= 1e-12 * scale)
      throw Error(source + ": " + where_quad(m, e) + " has zero area");
    if (area2 < 0)
      throw Error(source + ": " + where_quad(m, e) + " is inverted (its corners run clockwise)");
    if (!seen.insert(sorted).second)
      throw Error(source + ": " + where_quad(m, e) + " duplicates another quadrilateral");
  }
}

}  // namespace

void check_mesh(const Mesh& m, const std::string& source) {
  for (int i = 0; i < m.num_nodes(); ++i) {
    if (!m.x.col(i).allFinite())
      throw Error(source + ": node " + std::to_string(i + 1) + " has a non-finite coordinate");
    if (m.x.col(i).cwiseAbs().maxCoeff() > limits::kMaxCoordinate)
      throw Error(source + ": node " + std::to_string(i + 1) + " lies " +
                  fmt_number(m.x.col(i).cwiseAbs().maxCoeff()) +
                  " from the origin; homesh accepts coordinates up to " +
                  fmt_number(limits::kMaxCoordinate));
  }
  // Each triangle's sorted corner triple, then the triples sorted: a duplicate
  // is a run of equal triples (a std::set of them cost a second at 1e6 triangles).
  std::vector<std::pair<std::array<int, 3>, int>> corners;
  corners.reserve(m.num_triangles());
  for (int e = 0; e < m.num_triangles(); ++e) {
    std::array<int, 3> c = {m.tri(0, e), m.tri(1, e), m.tri(2, e)};
    const Eigen::Vector2d a = m.x.col(c[0]), b = m.x.col(c[1]), d = m.x.col(c[2]);
    const double area2 = (b - a).x() * (d - a).y() - (b - a).y() * (d - a).x();
    const double scale =
        std::max({(b - a).squaredNorm(), (d - a).squaredNorm(), (d - b).squaredNorm()});
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
      throw Error(source + ": " + where(m, e) + " repeats a corner node");
    if (std::abs(area2) <= 1e-12 * scale)
      throw Error(source + ": " + where(m, e) + " has zero area");
    if (area2 < 0)
      throw Error(source + ": " + where(m, e) + " is inverted (its corners run clockwise)");
    std::sort(c.begin(), c.end());
    corners.push_back({c, e});
  }
  std::sort(corners.begin(), corners.end());
  // The first triangle, in order, that repeats an earlier one: of each run of
  // equal triples (ascending triangle index within it), its second.
  int repeat = -1;
  for (std::size_t k = 1; k < corners.size(); ++k) {
    const bool second = corners[k].first == corners[k - 1].first &&
                        (k == 1 || corners[k - 1].first != corners[k - 2].first);
    if (second && (repeat < 0 || corners[k].second < repeat)) repeat = corners[k].second;
  }
  if (repeat >= 0) throw Error(source + ": " + where(m, repeat) + " duplicates another triangle");
  check_quads(m, source);
  check_manifold(m, source);
}

}  // namespace homesh
