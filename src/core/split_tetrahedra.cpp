#include "core/split_tetrahedra.h"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>

#include "core/error.h"
#include "element/barycentric_indices.h"
#include "element/tet_lagrange_basis.h"

namespace homesh {
namespace {

// A child's four corners in its parent's barycentric coordinates, each times q.
using ChildCorners = std::array<std::array<int, 4>, 4>;

struct ParentSplit {
  int tet = 0;
  int q = 1;
  std::vector<ChildCorners> children;  // children[0] takes the parent's place
};

// Splits each parent into its children (see split_at_centroid for the node
// placement). A new node is identified across parents by the global corners of
// the parent face, edge or interior it lies in and its reduced coordinates
// there, so children of neighbouring parents share the nodes of a shared face.
std::vector<int> split_parents(VolumeMesh& m, const std::vector<ParentSplit>& plan) {
  std::vector<int> from(static_cast<std::size_t>(m.num_tetrahedra()));
  for (int e = 0; e < m.num_tetrahedra(); ++e) from[static_cast<std::size_t>(e)] = e;
  if (plan.empty()) return from;
  const int p = m.order;
  const Eigen::MatrixXi b = barycentric_indices(4, p);
  const Eigen::Index n = b.cols();
  const auto key = [p](int i0, int i1, int i2, int i3) {
    return ((i0 * (p + 1) + i1) * (p + 1) + i2) * (p + 1) + i3;
  };
  std::vector<int> local(static_cast<std::size_t>((p + 1) * (p + 1) * (p + 1) * (p + 1)), -1);
  for (Eigen::Index k = 0; k < n; ++k)
    local[static_cast<std::size_t>(key(b(0, k), b(1, k), b(2, k), b(3, k)))] = static_cast<int>(k);
  const TetLagrangeBasis basis(p);

  const int parents = m.num_tetrahedra();
  Eigen::Index added = 0;
  for (const ParentSplit& s : plan) {
    if (s.tet < 0 || s.tet >= parents)
      throw Error("split tetrahedra: no tetrahedron " + std::to_string(s.tet));
    added += static_cast<Eigen::Index>(s.children.size()) - 1;
  }
  m.tet.conservativeResize(Eigen::NoChange, parents + added);
  std::vector<Eigen::Vector3d> new_x;
  std::map<std::array<std::pair<int, int>, 5>, int> made;  // (corner, weight)s, total -> node
  // The node at weights w (times q p) of the parent with nodes X: made once.
  const auto new_node = [&](const ParentSplit& s, const Eigen::VectorXi& parent,
                            const Eigen::Matrix3Xd& X, const std::array<int, 4>& w) {
    int g = s.q * p;
    for (const int x : w) g = std::gcd(g, x);
    std::array<std::pair<int, int>, 5> id{};
    id.fill({-1, 0});
    for (int j = 0; j < 4; ++j)
      if (w[j] > 0) id[static_cast<std::size_t>(j)] = {parent(j), w[j] / g};
    std::sort(id.begin(), id.begin() + 4);
    id[4] = {-2, s.q * p / g};
    auto [it, fresh] = made.try_emplace(id, m.num_nodes() + static_cast<int>(new_x.size()));
    if (fresh) {
      const Eigen::Vector3d uvw(w[1], w[2], w[3]);
      new_x.push_back(X * basis.values(uvw / (s.q * p)));  // Eq: x = sum N_k X_k
    }
    return it->second;
  };
  int next = parents;
  for (const ParentSplit& s : plan) {
    const int e = s.tet;
    const Eigen::Matrix3Xd X = m.tetrahedron_nodes(e);
    const Eigen::VectorXi parent = m.tet.col(e);
    for (std::size_t c = 0; c < s.children.size(); ++c) {
      const Eigen::Index col = c == 0 ? e : next++;
      for (Eigen::Index k = 0; k < n; ++k) {
        std::array<int, 4> w{0, 0, 0, 0};  // sums to q p
        for (int v = 0; v < 4; ++v)
          for (int j = 0; j < 4; ++j) w[j] += b(v, k) * s.children[c][v][j];
        if (w[0] % s.q == 0 && w[1] % s.q == 0 && w[2] % s.q == 0 && w[3] % s.q == 0) {
          m.tet(k, col) = parent(
              local[static_cast<std::size_t>(key(w[0] / s.q, w[1] / s.q, w[2] / s.q, w[3] / s.q))]);
        } else {
          m.tet(k, col) = new_node(s, parent, X, w);
        }
      }
      if (c > 0) {
        m.tet_entity.push_back(m.tet_entity[static_cast<std::size_t>(e)]);
        from.push_back(e);
      }
    }
  }
  const int old_nodes = m.num_nodes();
  m.x.conservativeResize(Eigen::NoChange, old_nodes + static_cast<Eigen::Index>(new_x.size()));
  m.node_class.resize(m.node_class.size() + new_x.size());
  // Each new node lies inside the volume (the split edges and faces are not
  // on the boundary); its entity is that of a parent that made it.
  for (Eigen::Index e = 0; e < m.tet.cols(); ++e)
    for (Eigen::Index k = 0; k < n; ++k) {
      const int i = m.tet(k, e);
      if (i >= old_nodes) m.node_class[static_cast<std::size_t>(i)] = {3, m.tet_entity[e]};
    }
  for (std::size_t i = 0; i < new_x.size(); ++i)
    m.x.col(old_nodes + static_cast<Eigen::Index>(i)) = new_x[i];
  const std::vector<int> perm = group_by_entity(m);
  if (perm.empty()) return from;
  std::vector<int> grouped(perm.size());
  for (std::size_t k = 0; k < perm.size(); ++k)
    grouped[k] = from[static_cast<std::size_t>(perm[k])];
  return grouped;
}

// Child f of a split at a point P (its weights `at`, times q): the parent with
// corner f replaced by P.
ChildCorners replace_corner(int f, const std::array<int, 4>& at, int q) {
  ChildCorners c{};
  for (int v = 0; v < 4; ++v)
    for (int j = 0; j < 4; ++j) c[v][j] = v == f ? at[j] : (j == v ? q : 0);
  return c;
}

}  // namespace

std::vector<int> split_at_centroid(VolumeMesh& m, const std::vector<int>& which) {
  std::vector<ParentSplit> plan;
  for (const int e : which) {
    ParentSplit s;
    s.tet = e;
    s.q = 4;
    for (int f = 0; f < 4; ++f) s.children.push_back(replace_corner(f, {1, 1, 1, 1}, 4));
    plan.push_back(s);
  }
  return split_parents(m, plan);
}

std::vector<int> split_edge(VolumeMesh& m, int a, int b) {
  if (a == b || a < 0 || b < 0 || a >= m.num_nodes() || b >= m.num_nodes())
    throw Error("split_edge: no edge between nodes " + std::to_string(a) + " and " +
                std::to_string(b));
  std::vector<ParentSplit> plan;
  for (int e = 0; e < m.num_tetrahedra(); ++e) {
    int ia = -1, ib = -1;
    for (int c = 0; c < 4; ++c) {
      if (m.tet(c, e) == a) ia = c;
      if (m.tet(c, e) == b) ib = c;
    }
    if (ia < 0 || ib < 0) continue;
    ParentSplit s;
    s.tet = e;
    s.q = 2;
    std::array<int, 4> mid{0, 0, 0, 0};
    mid[ia] = mid[ib] = 1;
    s.children = {replace_corner(ib, mid, 2), replace_corner(ia, mid, 2)};
    plan.push_back(s);
  }
  if (plan.empty())
    throw Error("split_edge: no tetrahedron has the edge between nodes " + std::to_string(a) +
                " and " + std::to_string(b));
  return split_parents(m, plan);
}

std::vector<int> wall_capped(const VolumeMesh& m, const std::vector<char>& bad) {
  std::vector<int> out;
  for (int e = 0; e < m.num_tetrahedra(); ++e) {
    if (!bad[static_cast<std::size_t>(e)]) continue;
    bool wall = true;
    for (int c = 0; c < 4 && wall; ++c) wall = m.node_class[m.tet(c, e)].dim < 3;
    if (wall) out.push_back(e);
  }
  return out;
}

}  // namespace homesh
