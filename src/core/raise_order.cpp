#include "core/raise_order.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/error.h"
#include "element/quad_reference_nodes.h"
#include "element/reference_nodes.h"

namespace homesh {
namespace {

// An edge between corner nodes lo < hi (indices in the raised mesh): the
// surface of its first 2D element and the first boundary line on it (-1 if
// none), and the first of its p-1 nodes.
struct Edge {
  int lo = -1;
  int hi = -1;
  int surface = -1;
  int line = -1;
  int first_node = -1;
};

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

// New index of every node of m: -1 for the nodes used only as edge or interior
// nodes of order q > 1, consecutive numbers for the others in original order.
std::vector<int> corner_renumbering(const Mesh& m) {
  enum : char { kUnused, kHighOrder, kCorner };
  std::vector<char> role(m.num_nodes(), kUnused);
  auto mark = [&role](const Eigen::MatrixXi& elements, int corners) {
    for (Eigen::Index e = 0; e < elements.cols(); ++e)
      for (Eigen::Index i = corners; i < elements.rows(); ++i)
        if (role[elements(i, e)] == kUnused) role[elements(i, e)] = kHighOrder;
    for (Eigen::Index e = 0; e < elements.cols(); ++e)
      for (int i = 0; i < corners; ++i) role[elements(i, e)] = kCorner;
  };
  mark(m.tri, 3);
  mark(m.quad, 4);
  mark(m.line, 2);
  for (int n : m.point_node) role[n] = kCorner;
  std::vector<int> renumber(m.num_nodes(), -1);
  int next = 0;
  for (int n = 0; n < m.num_nodes(); ++n)
    if (role[n] != kHighOrder) renumber[n] = next++;
  return renumber;
}

}  // namespace

Mesh raise_order(const Mesh& m, int p) {
  if (p < 1 || p > kMaxOrder)
    throw Error("raise_order: order " + std::to_string(p) + " out of range 1.." +
                std::to_string(kMaxOrder));
  const int per_edge = p - 1;
  const int per_interior = (p - 1) * (p - 2) / 2;
  const int per_quad_interior = (p - 1) * (p - 1);

  Mesh r;
  r.order = p;
  r.tri_entity = m.tri_entity;
  r.quad_entity = m.quad_entity;
  r.line_entity = m.line_entity;
  r.point_entity = m.point_entity;
  r.entities = m.entities;
  r.physicals = m.physicals;

  const std::vector<int> renumber = corner_renumbering(m);
  r.tri.resize(triangle_node_count(p), m.num_triangles());
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int i = 0; i < 3; ++i) r.tri(i, e) = renumber[m.tri(i, e)];
  r.quad.resize(quad_node_count(p), m.num_quads());
  for (int e = 0; e < m.num_quads(); ++e)
    for (int i = 0; i < 4; ++i) r.quad(i, e) = renumber[m.quad(i, e)];
  r.line.resize(p + 1, m.num_lines());
  for (int e = 0; e < m.num_lines(); ++e)
    for (int i = 0; i < 2; ++i) r.line(i, e) = renumber[m.line(i, e)];
  for (int n : m.point_node) r.point_node.push_back(renumber[n]);

  // Unique edges, triangles' first, then quadrilaterals', and the slot of each element edge.
  std::vector<Edge> edges;
  std::unordered_map<std::uint64_t, int> edge_of_key;
  edge_of_key.reserve(3 * m.num_triangles() / 2 + 2 * m.num_quads() + m.num_lines() + 1);
  auto find_or_add = [&](int a, int b) {
    const int next_edge = static_cast<int>(edges.size());
    const auto [it, added] = edge_of_key.try_emplace(edge_key(a, b), next_edge);
    if (added) edges.push_back({std::min(a, b), std::max(a, b)});
    return it->second;
  };
  Eigen::Matrix3Xi tri_edge(3, m.num_triangles());
  for (int e = 0; e < m.num_triangles(); ++e) {
    for (int k = 0; k < 3; ++k) {
      tri_edge(k, e) = find_or_add(r.tri(k, e), r.tri((k + 1) % 3, e));
      if (edges[tri_edge(k, e)].surface < 0) edges[tri_edge(k, e)].surface = m.tri_entity[e];
    }
  }
  Eigen::Matrix4Xi quad_edge(4, m.num_quads());
  for (int e = 0; e < m.num_quads(); ++e) {
    for (int k = 0; k < 4; ++k) {
      quad_edge(k, e) = find_or_add(r.quad(k, e), r.quad((k + 1) % 4, e));
      if (edges[quad_edge(k, e)].surface < 0) edges[quad_edge(k, e)].surface = m.quad_entity[e];
    }
  }
  std::vector<int> line_edge(m.num_lines());
  for (int e = 0; e < m.num_lines(); ++e) {
    line_edge[e] = find_or_add(r.line(0, e), r.line(1, e));
    if (edges[line_edge[e]].line < 0) edges[line_edge[e]].line = e;
  }

  // Node table: kept corners, then edge nodes, then interior nodes.
  const int num_corners = static_cast<int>(
      std::count_if(renumber.begin(), renumber.end(), [](int n) { return n >= 0; }));
  const int num_nodes = num_corners + per_edge * static_cast<int>(edges.size()) +
                        per_interior * m.num_triangles() + per_quad_interior * m.num_quads();
  r.x.resize(2, num_nodes);
  r.node_class.resize(num_nodes);
  for (int n = 0; n < m.num_nodes(); ++n) {
    if (renumber[n] < 0) continue;
    r.x.col(renumber[n]) = m.x.col(n);
    r.node_class[renumber[n]] = m.node_class[n];
  }

  const Eigen::RowVectorXd t = reference_line_nodes(p);
  int next = num_corners;
  for (Edge& edge : edges) {
    edge.first_node = next;
    NodeClass cls{2, edge.surface};
    double u_lo = std::numeric_limits<double>::quiet_NaN(), u_hi = u_lo;
    if (edge.line >= 0) {
      cls = NodeClass{1, m.line_entity[edge.line]};
      const int a = r.line(0, edge.line), b = r.line(1, edge.line);
      const bool forward = a == edge.lo;
      u_lo = r.node_class[forward ? a : b].u;
      u_hi = r.node_class[forward ? b : a].u;
    }
    const Eigen::Vector2d x_lo = r.x.col(edge.lo), x_hi = r.x.col(edge.hi);
    for (int i = 1; i < p; ++i, ++next) {
      const double s = t(i + 1);
      r.x.col(next) = (1.0 - s) * x_lo + s * x_hi;
      r.node_class[next] = cls;
      r.node_class[next].u = (1.0 - s) * u_lo + s * u_hi;  // NaN if either end's is
    }
  }

  // The i-th (from 0) node of `edge` for an element walking it from corner a.
  auto edge_node = [&](const Edge& edge, int a, int i) {
    return a == edge.lo ? edge.first_node + i : edge.first_node + per_edge - 1 - i;
  };
  for (int e = 0; e < m.num_lines(); ++e)
    for (int i = 0; i < per_edge; ++i)
      r.line(2 + i, e) = edge_node(edges[line_edge[e]], r.line(0, e), i);

  const Eigen::Matrix2Xd interior = reference_nodes(p).rightCols(per_interior);
  for (int e = 0; e < m.num_triangles(); ++e) {
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < per_edge; ++i)
        r.tri(3 + k * per_edge + i, e) = edge_node(edges[tri_edge(k, e)], r.tri(k, e), i);
    const Eigen::Vector2d x0 = r.x.col(r.tri(0, e));
    Eigen::Matrix2d A;
    A << r.x.col(r.tri(1, e)) - x0, r.x.col(r.tri(2, e)) - x0;
    for (int i = 0; i < per_interior; ++i, ++next) {
      r.tri(3 + 3 * per_edge + i, e) = next;
      r.x.col(next) = x0 + A * interior.col(i);
      r.node_class[next] = NodeClass{2, m.tri_entity[e]};
    }
  }
  // Quadrilaterals: edges 0-1, 1-2, 2-3, 3-0; interior nodes by the bilinear map.
  const Eigen::Matrix2Xd quad_interior = quad_reference_nodes(p).rightCols(per_quad_interior);
  for (int e = 0; e < m.num_quads(); ++e) {
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < per_edge; ++i)
        r.quad(4 + k * per_edge + i, e) = edge_node(edges[quad_edge(k, e)], r.quad(k, e), i);
    const Eigen::Vector2d x0 = r.x.col(r.quad(0, e)), x1 = r.x.col(r.quad(1, e)),
                          x2 = r.x.col(r.quad(2, e)), x3 = r.x.col(r.quad(3, e));
    for (int i = 0; i < per_quad_interior; ++i, ++next) {
      const double u = quad_interior(0, i), v = quad_interior(1, i);
      r.quad(4 + 4 * per_edge + i, e) = next;
      r.x.col(next) = (1 - u) * (1 - v) * x0 + u * (1 - v) * x1 + u * v * x2 + (1 - u) * v * x3;
      r.node_class[next] = NodeClass{2, m.quad_entity[e]};
    }
  }
  return r;
}

}  // namespace homesh
