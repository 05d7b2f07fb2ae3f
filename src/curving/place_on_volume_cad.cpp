#include "curving/place_on_volume_cad.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"
#include "element/barycentric_indices.h"

namespace homesh {
namespace {

using Entity2 = std::pair<int, int>;  // (dim, tag)

class Placer {
 public:
  Placer(VolumeMesh& m, const VolumeCad& cad) : m_(m), cad_(cad) {
    corner_.assign(static_cast<std::size_t>(m.num_nodes()), 0);
    for (Eigen::Index e = 0; e < m.tet.cols(); ++e)
      for (int i = 0; i < 4; ++i) corner_[m.tet(i, e)] = 1;
    for (Eigen::Index e = 0; e < m.tri.cols(); ++e)
      for (int i = 0; i < 3; ++i) corner_[m.tri(i, e)] = 1;
    for (Eigen::Index e = 0; e < m.line.cols(); ++e)
      for (int i = 0; i < 2; ++i) corner_[m.line(i, e)] = 1;
    done_.assign(corner_.size(), 0);
    r_.displacement = Eigen::Matrix3Xd::Zero(3, m.num_nodes());
  }

  bool geometry(int dim, int tag) {
    const auto [it, fresh] = geometry_.try_emplace({dim, tag}, false);
    if (fresh) it->second = cad_.has_geometry(dim, tag);
    return it->second;
  }

  // Interpolated requests from the elements of conn (corners rows) on entities of dim.
  void by_parameters(const Eigen::MatrixXi& conn, const std::vector<int>& entity, int corners,
                     int dim) {
    if (conn.cols() == 0) return;
    const Eigen::MatrixXi b = barycentric_indices(corners, m_.order);
    // The corners' parameters on each element's entity: the node's own, else asked.
    std::map<Entity2, std::vector<int>> ask;
    for (Eigen::Index e = 0; e < conn.cols(); ++e) {
      if (!geometry(dim, entity[e])) continue;
      for (int c = 0; c < corners; ++c) {
        const int i = conn(c, e);
        if (!known(i, dim, entity[e])) ask[{dim, entity[e]}].push_back(i);
      }
    }
    for (auto& [ent, nodes] : ask) {
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
      Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(nodes.size()));
      for (std::size_t k = 0; k < nodes.size(); ++k)
        x.col(static_cast<Eigen::Index>(k)) = m_.x.col(nodes[k]);
      const Eigen::MatrixXd uv = cad_.parameters(ent.first, ent.second, x);
      for (std::size_t k = 0; k < nodes.size(); ++k)
        if (uv.cols() == x.cols())
          asked_[{nodes[k], ent.second * 4 + ent.first}] = uv.col(static_cast<Eigen::Index>(k));
    }
    // Each new node on the element's entity, once: its interpolated parameters.
    for (Eigen::Index e = 0; e < conn.cols(); ++e) {
      const int tag = entity[e];
      if (!geometry(dim, tag)) continue;
      double longest = 0;
      for (int a = 0; a < corners; ++a)
        for (int c = a + 1; c < corners; ++c)
          longest = std::max(longest, (m_.x.col(conn(a, e)) - m_.x.col(conn(c, e))).norm());
      for (Eigen::Index k = corners; k < conn.rows(); ++k) {
        const int i = conn(k, e);
        const VolumeNodeClass& cls = m_.node_class[i];
        if (corner_[i] || done_[i] || cls.dim != dim || cls.tag != tag) continue;
        Eigen::VectorXd uv = Eigen::VectorXd::Zero(dim);
        bool ok = true;
        for (int c = 0; c < corners && ok; ++c) {
          const Eigen::VectorXd at = parameters(conn(c, e), dim, tag);
          ok = at.allFinite();
          if (ok) uv += (double(b(c, k)) / m_.order) * at;
        }
        done_[i] = 1;
        if (!ok) {
          fallback_[{dim, tag}].push_back(i);
          continue;
        }
        Request& q = requests_[{dim, tag}];
        q.nodes.push_back(i);
        q.params.push_back(uv);
        q.reach.push_back(0.5 * longest);
      }
    }
  }

  // Evaluates the requests, checks them, projects what failed and what is left.
  VolumePlacement finish() {
    for (auto& [ent, q] : requests_) {
      Eigen::MatrixXd params(ent.first, static_cast<Eigen::Index>(q.nodes.size()));
      for (std::size_t k = 0; k < q.nodes.size(); ++k)
        params.col(static_cast<Eigen::Index>(k)) = q.params[k];
      Eigen::Matrix3Xd straight(3, params.cols());
      for (std::size_t k = 0; k < q.nodes.size(); ++k)
        straight.col(static_cast<Eigen::Index>(k)) = m_.x.col(q.nodes[k]);
      const std::vector<char> converged = newton_projection(ent, straight, q.reach, params);
      const Eigen::Matrix3Xd y = cad_.value(ent.first, ent.second, params);
      for (std::size_t k = 0; k < q.nodes.size(); ++k) {
        const auto c = static_cast<Eigen::Index>(k);
        const int i = q.nodes[k];
        if (!converged[k] || y.cols() != params.cols() || !y.col(c).allFinite() ||
            (y.col(c) - m_.x.col(i)).norm() > q.reach[k]) {
          fallback_[ent].push_back(i);
          continue;
        }
        move(i, y.col(c), params.col(c), ent.first);
        ++r_.by_parameters;
      }
    }
    // Nodes on CAD in no line or triangle of theirs.
    for (int i = 0; i < m_.num_nodes(); ++i) {
      const VolumeNodeClass& c = m_.node_class[i];
      if (!corner_[i] && !done_[i] && (c.dim == 1 || c.dim == 2) && geometry(c.dim, c.tag))
        fallback_[{c.dim, c.tag}].push_back(i);
    }
    for (const auto& [ent, nodes] : fallback_) {
      Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(nodes.size()));
      for (std::size_t k = 0; k < nodes.size(); ++k)
        x.col(static_cast<Eigen::Index>(k)) = m_.x.col(nodes[k]);
      const Eigen::Matrix3Xd y = cad_.closest(ent.first, ent.second, x);
      if (y.cols() != x.cols() || !y.allFinite())
        throw Error("curve: the CAD's closest points on entity (" + std::to_string(ent.first) +
                    ", " + std::to_string(ent.second) + ") are not all finite");
      const Eigen::MatrixXd params = cad_.parameters(ent.first, ent.second, y);
      for (std::size_t k = 0; k < nodes.size(); ++k) {
        const auto c = static_cast<Eigen::Index>(k);
        move(nodes[k], y.col(c),
             params.cols() == x.cols() ? Eigen::VectorXd(params.col(c))
                                       : Eigen::VectorXd::Constant(ent.first, NAN),
             ent.first);
        ++r_.by_projection;
      }
    }
    return std::move(r_);
  }

 private:
  struct Request {
    std::vector<int> nodes;
    std::vector<Eigen::VectorXd> params;
    std::vector<double> reach;
  };

  // Gauss-Newton steps from the interpolated parameters towards those of the
  // straight nodes' closest points: what projection gives, by evaluations only
  // (a projection on a B-spline surface cost OCC 0.3 ms per point, a third of
  // the whole curving of a 4810-tetrahedron mesh at p = 2). Returns, per node,
  // whether the steps converged (the last one shorter than 1e-4 of its reach:
  // the point is on the CAD whatever the steps, only its place along it waits)
  // to parameters within the entity's range: near a degenerate point (a
  // sphere's pole) they need not, and the node is projected instead.
  std::vector<char> newton_projection(const Entity2& ent, const Eigen::Matrix3Xd& straight,
                                      const std::vector<double>& reach,
                                      Eigen::MatrixXd& params) const {
    const int dim = ent.first;
    const auto n = params.cols();
    std::vector<char> converged(static_cast<std::size_t>(n), 0);
    for (int step = 0; step <= kNewtonSteps; ++step) {
      const Eigen::Matrix3Xd y = cad_.value(dim, ent.second, params);
      const Eigen::MatrixXd d = cad_.derivatives(dim, ent.second, params);
      if (y.cols() != n || d.cols() != n) return std::vector<char>(static_cast<std::size_t>(n), 0);
      for (Eigen::Index k = 0; k < n; ++k) {
        const Eigen::Vector3d r = straight.col(k) - y.col(k);
        if (!r.allFinite() || !d.col(k).allFinite()) continue;
        Eigen::VectorXd delta(dim);
        Eigen::Vector3d moved;
        if (dim == 1) {
          const Eigen::Vector3d t = d.col(k);
          if (!(t.squaredNorm() > 0)) continue;
          delta(0) = t.dot(r) / t.squaredNorm();
          moved = delta(0) * t;
        } else {
          Eigen::Matrix<double, 3, 2> J;
          J << d.col(k).head<3>(), d.col(k).tail<3>();
          const Eigen::Matrix2d N = J.transpose() * J;
          if (!(N.determinant() > 1e-12 * N.trace() * N.trace())) continue;
          delta = N.inverse() * (J.transpose() * r);
          moved = J * delta;
        }
        // The last evaluation only measures the step it would take.
        if (step == kNewtonSteps) {
          converged[k] = moved.norm() <= 1e-4 * reach[k] ? 1 : 0;
          continue;
        }
        params.col(k) += delta;
      }
    }
    const Eigen::MatrixXd range = cad_.bounds(dim, ent.second);
    for (Eigen::Index k = 0; k < n; ++k)
      for (int a = 0; a < dim && converged[k]; ++a) {
        const double lo = range(a, 0), hi = range(a, 1), slack = 1e-9 * (hi - lo);
        converged[k] = std::isfinite(lo) && std::isfinite(hi) && params(a, k) >= lo - slack &&
                       params(a, k) <= hi + slack;
      }
    return converged;
  }

  static constexpr int kNewtonSteps = 4;

  bool known(int i, int dim, int tag) const {
    const VolumeNodeClass& c = m_.node_class[i];
    return c.dim == dim && c.tag == tag && std::isfinite(c.u) && (dim == 1 || std::isfinite(c.v));
  }

  // Node i's parameters on entity (dim, tag): its own or those asked (NaN if neither).
  Eigen::VectorXd parameters(int i, int dim, int tag) const {
    if (known(i, dim, tag)) {
      const VolumeNodeClass& c = m_.node_class[i];
      return dim == 1 ? Eigen::VectorXd::Constant(1, c.u) : Eigen::Vector2d(c.u, c.v).eval();
    }
    const auto it = asked_.find({i, tag * 4 + dim});
    return it == asked_.end() ? Eigen::VectorXd::Constant(dim, NAN) : it->second;
  }

  void move(int i, const Eigen::Vector3d& y, const Eigen::VectorXd& params, int dim) {
    r_.displacement.col(i) = y - m_.x.col(i);
    r_.largest_move = std::max(r_.largest_move, r_.displacement.col(i).norm());
    m_.x.col(i) = y;
    VolumeNodeClass& c = m_.node_class[i];
    c.u = params(0);
    if (dim == 2) c.v = params(1);
  }

  VolumeMesh& m_;
  const VolumeCad& cad_;
  std::vector<char> corner_, done_;
  std::map<Entity2, bool> geometry_;
  std::map<std::pair<int, int>, Eigen::VectorXd> asked_;  // (node, tag * 4 + dim)
  std::map<Entity2, Request> requests_;
  std::map<Entity2, std::vector<int>> fallback_;
  VolumePlacement r_;
};

}  // namespace

VolumePlacement place_on_volume_cad(VolumeMesh& m, const VolumeCad& cad) {
  Placer placer(m, cad);
  placer.by_parameters(m.line, m.line_entity, 2, 1);
  placer.by_parameters(m.tri, m.tri_entity, 3, 2);
  return placer.finish();
}

}  // namespace homesh
