#include "core/check_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <sstream>
#include <unordered_map>

#include "core/error.h"
#include "core/input_limits.h"
#include "element/line_lagrange.h"
#include "element/quadrature.h"

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

// Twice the signed area of an element, and the square of its longest
// corner-to-corner side (its scale): of its corners' polygon, and, for a
// curved element (order p, Gmsh order: the corners, then each edge's p - 1
// nodes from its first corner to its second, equispaced in the edge's
// parameter), the larger of that and the boundary integral of x dy - y dx
// along the edges' polynomials (degree p, the integrand 2p - 1: exact by p
// Gauss points), which is the integral of det J over the element. So an
// element is refused as inverted only if both are clockwise: a valid thin
// element round a leading edge at p = 3 can have its three corners (and even
// the polygon through all its boundary nodes) clockwise, its edges' chords
// cutting across it, and homesh certified and wrote it; an element folded
// inside, its corners counter-clockwise, is left to the certification.
std::pair<double, double> boundary_area2(const Mesh& m, const Eigen::MatrixXi& nodes, int e,
                                         int corners) {
  const int p = m.order;
  double scale = 0;
  for (int k = 0; k < corners; ++k)
    scale = std::max(scale,
                     (m.x.col(nodes((k + 1) % corners, e)) - m.x.col(nodes(k, e))).squaredNorm());
  double polygon = 0;
  for (int k = 0; k < corners; ++k) {
    const Eigen::Vector2d a = m.x.col(nodes(k, e)), b = m.x.col(nodes((k + 1) % corners, e));
    polygon += a.x() * b.y() - a.y() * b.x();
  }
  if (p == 1) return {polygon, scale};
  const LineQuadratureRule q = line_quadrature(2 * p - 1);
  double area2 = 0;
  std::vector<Eigen::Vector2d> edge(p + 1);
  std::vector<double> L(p + 1), dL(p + 1);
  for (int k = 0; k < corners; ++k) {
    edge[0] = m.x.col(nodes(k, e));
    for (int j = 1; j < p; ++j) edge[j] = m.x.col(nodes(corners + k * (p - 1) + j - 1, e));
    edge[p] = m.x.col(nodes((k + 1) % corners, e));
    for (Eigen::Index g = 0; g < q.points.size(); ++g) {
      line_lagrange(p, q.points(g), L.data(), dL.data());
      Eigen::Vector2d x = Eigen::Vector2d::Zero(), dx = Eigen::Vector2d::Zero();
      for (int i = 0; i <= p; ++i) {
        x += L[i] * edge[i];
        dx += dL[i] * edge[i];
      }
      area2 += q.weights(g) * (x.x() * dx.y() - x.y() * dx.x());
    }
  }
  return {std::max(polygon, area2), scale};
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
    const auto [area2, scale] = boundary_area2(m, m.quad, e, 4);
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
    const auto [area2, scale] = boundary_area2(m, m.tri, e, 3);
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
