#include "core/check_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <sstream>

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

// The edges' quadrature at order p and its scratch, made once for all elements.
struct EdgeQuadrature {
  int p;
  LineQuadratureRule q;
  std::vector<Eigen::Vector2d> edge;
  std::vector<double> L, dL;
  explicit EdgeQuadrature(int order)
      : p(order),
        q(line_quadrature(std::max(1, 2 * order - 1))),
        edge(order + 1),
        L(order + 1),
        dL(order + 1) {}
};

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
                                         int corners, EdgeQuadrature& eq) {
  const int p = eq.p;
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
  double area2 = 0;
  std::vector<Eigen::Vector2d>& edge = eq.edge;
  for (int k = 0; k < corners; ++k) {
    edge[0] = m.x.col(nodes(k, e));
    for (int j = 1; j < p; ++j) edge[j] = m.x.col(nodes(corners + k * (p - 1) + j - 1, e));
    edge[p] = m.x.col(nodes((k + 1) % corners, e));
    for (Eigen::Index g = 0; g < eq.q.points.size(); ++g) {
      line_lagrange(p, eq.q.points(g), eq.L.data(), eq.dL.data());
      Eigen::Vector2d x = Eigen::Vector2d::Zero(), dx = Eigen::Vector2d::Zero();
      for (int i = 0; i <= p; ++i) {
        x += eq.L[i] * edge[i];
        dx += eq.dL[i] * edge[i];
      }
      area2 += eq.q.weights(g) * (x.x() * dx.y() - x.y() * dx.x());
    }
  }
  return {std::max(polygon, area2), scale};
}

// Items of the mesh bucketed by a node in one counting-sort pass (compressed
// rows), each bucket then sorted on its own: linear in the mesh where a hash map
// of its edges and a sort of all its triangles' corner triples were not (on a
// 2354-triangle mesh they took 0.3 ms, a third of reading it from Gmsh).
template <typename Item>
struct NodeBuckets {
  std::vector<int> first;  ///< #nodes + 1: node v's items are items[first[v] .. first[v + 1])
  std::vector<Item> items;

  // each(f) calls f(node, item) once per item.
  template <typename Each>
  NodeBuckets(int nodes, Each each) : first(static_cast<std::size_t>(nodes) + 1, 0) {
    each([&](int v, const Item&) { ++first[v + 1]; });
    for (int v = 0; v < nodes; ++v) first[v + 1] += first[v];
    items.resize(static_cast<std::size_t>(first[nodes]));
    std::vector<int> next(first.begin(), first.end() - 1);
    each([&](int v, const Item& item) { items[next[v]++] = item; });
    for (int v = 0; v < nodes; ++v)
      std::sort(items.begin() + first[v], items.begin() + first[v + 1]);
  }
};

// Every corner edge bounds one or two elements (triangles or quadrilaterals):
// a third one sharing it makes the mesh non-manifold, which no stage can curve
// or layer. Named: the edge whose third use comes first, triangles' edges
// before quadrilaterals', each element's in order.
void check_manifold(const Mesh& m, const std::string& source) {
  const std::int64_t triangles = m.num_triangles();
  // An edge's use: (its larger node, the use's ordinal), bucketed by its smaller node.
  using Use = std::pair<int, std::int64_t>;
  const NodeBuckets<Use> edges(m.num_nodes(), [&](auto&& add) {
    const auto use = [&](int i, int j, std::int64_t ordinal) {
      add(std::min(i, j), Use{std::max(i, j), ordinal});
    };
    for (int e = 0; e < m.num_triangles(); ++e)
      for (int k = 0; k < 3; ++k) use(m.tri(k, e), m.tri((k + 1) % 3, e), 3 * std::int64_t{e} + k);
    for (int e = 0; e < m.num_quads(); ++e)
      for (int k = 0; k < 4; ++k)
        use(m.quad(k, e), m.quad((k + 1) % 4, e), 3 * triangles + 4 * std::int64_t{e} + k);
  });
  std::int64_t third = -1;
  int a = 0, b = 0;
  for (int v = 0; v < m.num_nodes(); ++v)
    for (int k = edges.first[v] + 2; k < edges.first[v + 1]; ++k) {
      const Use& u = edges.items[k];
      if (u.first != edges.items[k - 2].first) continue;
      if (k - 3 >= edges.first[v] && edges.items[k - 3].first == u.first) continue;  // a 4th use
      if (third < 0 || u.second < third) third = u.second, a = v, b = u.first;
    }
  if (third < 0) return;
  // The element is named only when it is at fault: formatting its place for every
  // edge cost a tenth of a layers stage at 1e6 triangles.
  const bool quad = third >= 3 * triangles;
  const int e = static_cast<int>(quad ? (third - 3 * triangles) / 4 : third / 3);
  throw Error(source + ": the edge between nodes " + std::to_string(a + 1) + " and " +
              std::to_string(b + 1) + " of " + (quad ? where_quad(m, e) : where(m, e)) +
              " is shared by three or more elements (a non-manifold mesh)");
}

// A quadrilateral's corners: distinct, counter-clockwise (Gmsh's order), of
// non-zero area, and not those of another quadrilateral.
void check_quads(const Mesh& m, const std::string& source, EdgeQuadrature& edges) {
  std::set<std::array<int, 4>> seen;
  for (int e = 0; e < m.num_quads(); ++e) {
    std::array<int, 4> c = {m.quad(0, e), m.quad(1, e), m.quad(2, e), m.quad(3, e)};
    const auto [area2, scale] = boundary_area2(m, m.quad, e, 4, edges);
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
  EdgeQuadrature edges(m.order);
  // Each triangle's sorted corner triple, bucketed by its first corner: a duplicate
  // is a run of equal triples in a bucket.
  std::vector<std::array<int, 3>> corners(static_cast<std::size_t>(m.num_triangles()));
  for (int e = 0; e < m.num_triangles(); ++e) {
    std::array<int, 3> c = {m.tri(0, e), m.tri(1, e), m.tri(2, e)};
    const auto [area2, scale] = boundary_area2(m, m.tri, e, 3, edges);
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
      throw Error(source + ": " + where(m, e) + " repeats a corner node");
    if (std::abs(area2) <= 1e-12 * scale)
      throw Error(source + ": " + where(m, e) + " has zero area");
    if (area2 < 0)
      throw Error(source + ": " + where(m, e) + " is inverted (its corners run clockwise)");
    std::sort(c.begin(), c.end());
    corners[e] = c;
  }
  using Rest = std::array<int, 3>;  // the other two corners, then the triangle
  const NodeBuckets<Rest> by_corner(m.num_nodes(), [&](auto&& add) {
    for (int e = 0; e < m.num_triangles(); ++e)
      add(corners[e][0], Rest{corners[e][1], corners[e][2], e});
  });
  // The first triangle, in order, that repeats an earlier one: of each run of
  // equal triples (ascending triangle index within it), its second.
  int repeat = -1;
  const auto same = [](const Rest& x, const Rest& y) { return x[0] == y[0] && x[1] == y[1]; };
  for (int v = 0; v < m.num_nodes(); ++v)
    for (int k = by_corner.first[v] + 1; k < by_corner.first[v + 1]; ++k) {
      const Rest& r = by_corner.items[k];
      const bool second = same(r, by_corner.items[k - 1]) &&
                          (k - 2 < by_corner.first[v] || !same(r, by_corner.items[k - 2]));
      if (second && (repeat < 0 || r[2] < repeat)) repeat = r[2];
    }
  if (repeat >= 0) throw Error(source + ": " + where(m, repeat) + " duplicates another triangle");
  check_quads(m, source, edges);
  check_manifold(m, source);
}

}  // namespace homesh
