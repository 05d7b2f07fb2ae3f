#include "core/raise_volume_order.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "core/error.h"
#include "element/barycentric_indices.h"

namespace homesh {
namespace {

// A lattice point of order p on a sub-simplex: its corners' node indices, in
// increasing order, with their barycentric indices (0 past the last corner).
struct LatticeKey {
  std::array<int, 4> node{-1, -1, -1, -1};
  std::array<int, 4> index{0, 0, 0, 0};
  bool operator==(const LatticeKey& o) const { return node == o.node && index == o.index; }
};

struct LatticeKeyHash {
  std::size_t operator()(const LatticeKey& k) const {
    std::size_t h = 0;
    for (int i = 0; i < 4; ++i)
      h = h * 1000003u ^ (static_cast<std::size_t>(static_cast<unsigned>(k.node[i])) * 16u +
                          static_cast<std::size_t>(k.index[i]));
    return h;
  }
};

class Raiser {
 public:
  Raiser(const VolumeMesh& m, int p) : p_(p) {
    // Corners and point elements survive, in their original order.
    std::vector<char> keep(static_cast<std::size_t>(m.num_nodes()), 0);
    const auto mark = [&](const Eigen::MatrixXi& conn, int corners) {
      for (Eigen::Index e = 0; e < conn.cols(); ++e)
        for (int i = 0; i < corners; ++i) keep[conn(i, e)] = 1;
    };
    mark(m.tet, 4);
    mark(m.tri, 3);
    mark(m.line, 2);
    for (int i : m.point_node) keep[i] = 1;
    old_to_new_.assign(keep.size(), -1);
    for (std::size_t i = 0; i < keep.size(); ++i)
      if (keep[i]) {
        old_to_new_[i] = static_cast<int>(x_.size());
        x_.push_back(m.x.col(static_cast<Eigen::Index>(i)));
        cls_.push_back(m.node_class[i]);
      }
  }

  // The columns of `conn` (corners first) at order p, entity `entity` of dim `dim`.
  Eigen::MatrixXi raise(const Eigen::MatrixXi& conn, int corners, int dim,
                        const std::vector<int>& entity) {
    const Eigen::MatrixXi b = barycentric_indices(corners, p_);
    Eigen::MatrixXi out(b.cols(), conn.cols());
    for (Eigen::Index e = 0; e < conn.cols(); ++e)
      for (Eigen::Index k = 0; k < b.cols(); ++k) {
        LatticeKey key;
        int used = 0;
        for (int c = 0; c < corners; ++c)
          if (b(c, k) > 0) {
            key.node[used] = old_to_new_[conn(c, e)];
            key.index[used] = b(c, k);
            ++used;
          }
        if (used == 1) {  // a corner
          out(k, e) = key.node[0];
          continue;
        }
        if (used == corners && dim == 3) {  // inside one tetrahedron: never shared
          out(k, e) = add_node(key, used, dim, entity[e], conn, e, b.col(k), corners);
          continue;
        }
        sort_key(key, used);
        const auto [it, fresh] = nodes_.try_emplace(key, -1);
        if (fresh) it->second = add_node(key, used, dim, entity[e], conn, e, b.col(k), corners);
        out(k, e) = it->second;
      }
    return out;
  }

  int old_to_new(int i) const { return old_to_new_[i]; }

  void finish(VolumeMesh& r) const {
    r.x.resize(3, static_cast<Eigen::Index>(x_.size()));
    for (std::size_t i = 0; i < x_.size(); ++i) r.x.col(static_cast<Eigen::Index>(i)) = x_[i];
    r.node_class = cls_;
  }

 private:
  static void sort_key(LatticeKey& key, int used) {
    for (int a = 1; a < used; ++a)
      for (int c = a; c > 0 && key.node[c - 1] > key.node[c]; --c) {
        std::swap(key.node[c - 1], key.node[c]);
        std::swap(key.index[c - 1], key.index[c]);
      }
  }

  int add_node(const LatticeKey& key, int used, int dim, int tag, const Eigen::MatrixXi& conn,
               Eigen::Index e, const Eigen::VectorXi& index, int corners) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int c = 0; c < used; ++c) x += (double(key.index[c]) / p_) * x_[key.node[c]];
    VolumeNodeClass cls{dim, tag};
    // Parameters interpolated from the element's corners, where all have them.
    if (dim == 1 || dim == 2) {
      double u = 0, v = 0;
      for (int c = 0; c < corners; ++c) {
        const VolumeNodeClass& k = cls_[old_to_new_[conn(c, e)]];
        const bool on = k.dim == dim && k.tag == tag;
        const double w = double(index(c)) / p_;
        u += w * (on ? k.u : std::numeric_limits<double>::quiet_NaN());
        v += w * (on ? k.v : std::numeric_limits<double>::quiet_NaN());
      }
      cls.u = u;
      if (dim == 2) cls.v = v;
    }
    x_.push_back(x);
    cls_.push_back(cls);
    return static_cast<int>(x_.size()) - 1;
  }

  int p_;
  std::vector<int> old_to_new_;
  std::vector<Eigen::Vector3d> x_;
  std::vector<VolumeNodeClass> cls_;
  std::unordered_map<LatticeKey, int, LatticeKeyHash> nodes_;
};

}  // namespace

VolumeMesh raise_volume_order(const VolumeMesh& m, int p) {
  if (p < 1 || p > kMaxTetrahedronOrder)
    throw Error("order p = " + std::to_string(p) + " is out of range: tetrahedra of order 1 to " +
                std::to_string(kMaxTetrahedronOrder));
  Raiser raiser(m, p);
  VolumeMesh r;
  r.order = p;
  r.line = raiser.raise(m.line, 2, 1, m.line_entity);
  r.tri = raiser.raise(m.tri, 3, 2, m.tri_entity);
  r.tet = raiser.raise(m.tet, 4, 3, m.tet_entity);
  raiser.finish(r);
  r.line_entity = m.line_entity;
  r.tri_entity = m.tri_entity;
  r.tet_entity = m.tet_entity;
  for (std::size_t k = 0; k < m.point_node.size(); ++k)
    r.point_node.push_back(raiser.old_to_new(m.point_node[k]));
  r.point_entity = m.point_entity;
  r.entities = m.entities;
  r.physicals = m.physicals;
  return r;
}

}  // namespace homesh
