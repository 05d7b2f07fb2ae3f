#include "core/split_tetrahedra.h"

#include <array>
#include <map>

#include "core/error.h"
#include "element/barycentric_indices.h"
#include "element/tet_lagrange_basis.h"

namespace homesh {

std::vector<int> split_at_centroid(VolumeMesh& m, const std::vector<int>& which) {
  std::vector<int> from(static_cast<std::size_t>(m.num_tetrahedra()));
  for (int e = 0; e < m.num_tetrahedra(); ++e) from[static_cast<std::size_t>(e)] = e;
  if (which.empty()) return from;
  const int p = m.order;
  const Eigen::MatrixXi b = barycentric_indices(4, p);
  const Eigen::Index n = b.cols();
  // Parent node of each lattice point: (p + 1)^4 table of the multi-index.
  const auto key = [p](int i0, int i1, int i2, int i3) {
    return ((i0 * (p + 1) + i1) * (p + 1) + i2) * (p + 1) + i3;
  };
  std::vector<int> local(static_cast<std::size_t>((p + 1) * (p + 1) * (p + 1) * (p + 1)), -1);
  for (Eigen::Index k = 0; k < n; ++k)
    local[static_cast<std::size_t>(key(b(0, k), b(1, k), b(2, k), b(3, k)))] = static_cast<int>(k);
  const TetLagrangeBasis basis(p);

  const int parents = m.num_tetrahedra();
  for (const int e : which)
    if (e < 0 || e >= parents)
      throw Error("split_at_centroid: no tetrahedron " + std::to_string(e));
  m.tet.conservativeResize(Eigen::NoChange, parents + 3 * static_cast<Eigen::Index>(which.size()));
  std::vector<Eigen::Vector3d> new_x;
  int next = parents;
  for (const int e : which) {
    const Eigen::Matrix3Xd X = m.tetrahedron_nodes(e);
    const Eigen::VectorXi parent = m.tet.col(e);
    std::map<std::array<int, 4>, int> made;  // 4p times the parent barycentric -> node
    for (int f = 0; f < 4; ++f) {
      const Eigen::Index col = f == 0 ? e : next++;
      for (Eigen::Index k = 0; k < n; ++k) {
        // The child's node k in the parent's barycentric coordinates, times 4p:
        // corner c weighs 4 at itself, M 1 at every corner.
        std::array<int, 4> s{0, 0, 0, 0};
        for (int c = 0; c < 4; ++c)
          for (int j = 0; j < 4; ++j) s[j] += b(c, k) * (c == f ? 1 : (j == c ? 4 : 0));
        if (s[0] % 4 == 0 && s[1] % 4 == 0 && s[2] % 4 == 0 && s[3] % 4 == 0) {
          const int at =
              local[static_cast<std::size_t>(key(s[0] / 4, s[1] / 4, s[2] / 4, s[3] / 4))];
          m.tet(k, col) = parent(at);
          continue;
        }
        auto [it, fresh] = made.try_emplace(s, m.num_nodes() + static_cast<int>(new_x.size()));
        if (fresh) {
          const Eigen::Vector3d uvw(s[1], s[2], s[3]);
          const Eigen::VectorXd N = basis.values(uvw / (4.0 * p));  // Eq: x = sum N_k X_k
          new_x.push_back(X * N);
        }
        m.tet(k, col) = it->second;
      }
      if (f > 0) {
        m.tet_entity.push_back(m.tet_entity[static_cast<std::size_t>(e)]);
        from.push_back(e);
      }
    }
  }
  const int old_nodes = m.num_nodes();
  m.x.conservativeResize(Eigen::NoChange, old_nodes + static_cast<Eigen::Index>(new_x.size()));
  m.node_class.resize(m.node_class.size() + new_x.size());
  // Each new node lies inside the parent whose children made it; its entity is
  // the parent's (the children of one parent share the parent's entity).
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
