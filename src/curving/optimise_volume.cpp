#include "curving/optimise_volume.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <deque>
#include <map>

#include "core/corner_tetrahedra.h"
#include "element/tet_lagrange_basis.h"
#include "element/tet_reference_nodes.h"
#include "fem/tet_elasticity.h"
#include "quality/jacobian_bounds.h"

namespace homesh {
namespace {

// The points the energy samples: the lattice of det J's degree 3(p-1) (at
// least 2), corners, edges and faces included, where det J is least on most
// curved elements (interior quadrature points alone let the optimiser hide a
// negative det J at a corner), equally weighted to the reference volume 1/6.
TetTabulation lattice_sampling(int p) {
  TetTabulation t;
  t.order = p;
  t.rule.points = tetrahedron_nodes(std::max(2, 3 * (p - 1)));
  const auto n = t.rule.points.cols();
  t.rule.weights = Eigen::VectorXd::Constant(n, 1.0 / (6.0 * static_cast<double>(n)));
  const TetLagrangeBasis basis(p);
  for (Eigen::Index q = 0; q < n; ++q) t.gradients.push_back(basis.gradients(t.rule.points.col(q)));
  return t;
}

// The derivative of det J: cof(J) = [j1 x j2, j2 x j0, j0 x j1] for J = [j0 j1 j2].
Eigen::Matrix3d cofactor(const Eigen::Matrix3d& J) {
  Eigen::Matrix3d C;
  C.col(0) = J.col(1).cross(J.col(2));
  C.col(1) = J.col(2).cross(J.col(0));
  C.col(2) = J.col(0).cross(J.col(1));
  return C;
}

// One patch: its elements, its movable nodes and how they move.
class Patch {
 public:
  Patch(VolumeMesh& m, const VolumeCad& cad, const TetTabulation& tab, std::vector<int> elements,
        const std::vector<char>& movable)
      : m_(m), cad_(cad), tab_(tab), elements_(std::move(elements)) {
    std::map<int, int> index;
    for (int e : elements_)
      for (Eigen::Index k = 0; k < m.tet.rows(); ++k) {
        const int i = m.tet(k, e);
        if (movable[i] && index.emplace(i, static_cast<int>(nodes_.size())).second)
          nodes_.push_back(i);
      }
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      const VolumeNodeClass& c = m.node_class[nodes_[k]];
      if (c.dim == 1 || c.dim == 2) sliding_[{c.dim, c.tag}].push_back(static_cast<int>(k));
    }
    // A sliding node stays within a quarter of its distance to the nearest other
    // node of its elements: inside its own face (or curve), away from the
    // trimmed edges a projection could cross.
    start_ = positions();
    radius_.assign(nodes_.size(), INFINITY);
    for (int e : elements_)
      for (Eigen::Index i = 0; i < m.tet.rows(); ++i) {
        const auto it = index.find(m.tet(i, e));
        if (it == index.end()) continue;
        for (Eigen::Index j = 0; j < m.tet.rows(); ++j)
          if (j != i)
            radius_[it->second] = std::min(
                radius_[it->second], 0.25 * (m.x.col(m.tet(i, e)) - m.x.col(m.tet(j, e))).norm());
      }
    // Each sliding node's plane (surface) or line (curve) of motion, from the
    // CAD's directions where it starts; a node whose direction the CAD cannot
    // give is held.
    slides_.assign(nodes_.size(), 0);
    projector_.assign(nodes_.size(), Eigen::Matrix3d::Identity());
    for (const auto& [entity, ks] : sliding_) {
      Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(ks.size()));
      for (std::size_t j = 0; j < ks.size(); ++j)
        x.col(static_cast<Eigen::Index>(j)) = start_.segment<3>(3 * ks[j]);
      const Eigen::Matrix3Xd d = cad.directions(entity.first, entity.second, x);
      for (std::size_t j = 0; j < ks.size(); ++j) {
        const Eigen::Vector3d n = d.col(static_cast<Eigen::Index>(j));
        const int k = ks[j];
        if (!n.allFinite()) {
          projector_[k].setZero();
          continue;
        }
        slides_[k] = 1;
        projector_[k] = entity.first == 2
                            ? Eigen::Matrix3d(Eigen::Matrix3d::Identity() - n * n.transpose())
                            : Eigen::Matrix3d(n * n.transpose());
      }
    }
    // J0_e, the straight element's det J (6 volumes), the energy's unit: never
    // below a thousandth of the patch's mean, should a linear element be flat.
    double sum = 0;
    for (int e : elements_) {
      Eigen::Matrix3d J;
      J << m.x.col(m.tet(1, e)) - m.x.col(m.tet(0, e)), m.x.col(m.tet(2, e)) - m.x.col(m.tet(0, e)),
          m.x.col(m.tet(3, e)) - m.x.col(m.tet(0, e));
      straight_.push_back(J.determinant());
      sum += std::abs(straight_.back());
    }
    for (double& j0 : straight_)
      j0 = std::max(j0, 1e-3 * sum / static_cast<double>(straight_.size()));
    local_.resize(m.tet.rows(), static_cast<Eigen::Index>(elements_.size()));
    for (std::size_t k = 0; k < elements_.size(); ++k)
      for (Eigen::Index i = 0; i < m.tet.rows(); ++i) {
        const auto it = index.find(m.tet(i, elements_[k]));
        local_(i, static_cast<Eigen::Index>(k)) = it == index.end() ? -1 : it->second;
      }
  }

  bool empty() const { return nodes_.empty(); }

  // The movable nodes' positions and classes, to restore a rejected result.
  struct State {
    Eigen::VectorXd z;
    std::vector<VolumeNodeClass> classes;
  };
  State state() const {
    State s{positions(), {}};
    for (int i : nodes_) s.classes.push_back(m_.node_class[i]);
    return s;
  }
  void restore(const State& s) {
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      m_.x.col(nodes_[k]) = s.z.segment<3>(3 * k);
      m_.node_class[nodes_[k]] = s.classes[k];
    }
  }
  const std::vector<int>& elements() const { return elements_; }

  Eigen::VectorXd positions() const {
    Eigen::VectorXd z(3 * nodes_.size());
    for (std::size_t k = 0; k < nodes_.size(); ++k) z.segment<3>(3 * k) = m_.x.col(nodes_[k]);
    return z;
  }

  // Puts z into the mesh, each sliding node's move from where it started
  // restricted to its tangent plane (surface) or line (curve) at the start and
  // to its radius (z updated). Off the CAD by the surface's curvature times the
  // move squared: snap() puts them back on it.
  void place(Eigen::VectorXd& z) {
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      if (!slides_[k]) continue;
      Eigen::Vector3d step = projector_[k] * (z.segment<3>(3 * k) - start_.segment<3>(3 * k));
      if (step.norm() > radius_[k]) step *= radius_[k] / step.norm();
      z.segment<3>(3 * k) = start_.segment<3>(3 * k) + step;
    }
    for (std::size_t k = 0; k < nodes_.size(); ++k) m_.x.col(nodes_[k]) = z.segment<3>(3 * k);
  }

  // The sliding nodes projected onto their CAD (one call per entity). False,
  // the mesh left as it was, if a projection is not finite or lands beyond
  // 1.5 radii (the node would have left its face).
  bool snap() {
    Eigen::VectorXd z = positions();
    for (const auto& [entity, ks] : sliding_) {
      Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(ks.size()));
      for (std::size_t j = 0; j < ks.size(); ++j)
        x.col(static_cast<Eigen::Index>(j)) = z.segment<3>(3 * ks[j]);
      const Eigen::Matrix3Xd y = cad_.closest(entity.first, entity.second, x);
      if (y.cols() != x.cols() || !y.allFinite()) return false;
      for (std::size_t j = 0; j < ks.size(); ++j) {
        const Eigen::Vector3d yj = y.col(static_cast<Eigen::Index>(j));
        if ((yj - start_.segment<3>(3 * ks[j])).norm() > 1.5 * radius_[ks[j]]) return false;
        z.segment<3>(3 * ks[j]) = yj;
      }
    }
    for (std::size_t k = 0; k < nodes_.size(); ++k) m_.x.col(nodes_[k]) = z.segment<3>(3 * k);
    return true;
  }

  // The CAD parameters of the sliding nodes where they are now (NaN if not found).
  void update_parameters() {
    for (const auto& [entity, ks] : sliding_) {
      Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(ks.size()));
      for (std::size_t j = 0; j < ks.size(); ++j)
        x.col(static_cast<Eigen::Index>(j)) = m_.x.col(nodes_[ks[j]]);
      const Eigen::MatrixXd params = cad_.parameters(entity.first, entity.second, x);
      for (std::size_t j = 0; j < ks.size(); ++j) {
        VolumeNodeClass& c = m_.node_class[nodes_[ks[j]]];
        const bool ok = params.cols() == x.cols();
        c.u = ok ? params(0, static_cast<Eigen::Index>(j)) : NAN;
        if (entity.first == 2)
          c.v = ok && params.rows() > 1 ? params(1, static_cast<Eigen::Index>(j)) : NAN;
      }
    }
  }

  // Smallest and mean det J over the patch's sample points, at the mesh's nodes.
  std::pair<double, double> determinants() const {
    double lo = INFINITY, sum = 0;
    int count = 0;
    for (int e : elements_) {
      const Eigen::Matrix3Xd X = m_.tetrahedron_nodes(e);
      for (const Eigen::Matrix3Xd& dN : tab_.gradients) {
        const double det = (X * dN.transpose()).determinant();
        lo = std::min(lo, det);
        sum += std::abs(det);
        ++count;
      }
    }
    return {lo, count ? sum / count : 0.0};
  }

  // The smallest det J_q / J0_e over the patch's samples.
  double lowest_normalised() const {
    double lo = INFINITY;
    for (std::size_t k = 0; k < elements_.size(); ++k) {
      const Eigen::Matrix3Xd X = m_.tetrahedron_nodes(elements_[k]);
      for (const Eigen::Matrix3Xd& dN : tab_.gradients)
        lo = std::min(lo, (X * dN.transpose()).determinant() / straight_[k]);
    }
    return lo;
  }

  // The energy of the header at the mesh's nodes with barrier b (below every
  // det J_q / J0_e; INFINITY where one is not), its gradient with respect to
  // the movable nodes.
  double energy(double b, Eigen::VectorXd* gradient) const {
    if (gradient) gradient->setZero(3 * static_cast<Eigen::Index>(nodes_.size()));
    double total = 0;
    const auto samples = static_cast<Eigen::Index>(tab_.gradients.size());
    for (std::size_t k = 0; k < elements_.size(); ++k) {
      const Eigen::Matrix3Xd X = m_.tetrahedron_nodes(elements_[k]);
      for (Eigen::Index q = 0; q < samples; ++q) {
        const Eigen::Matrix3Xd& dN = tab_.gradients[q];
        const Eigen::Matrix3d J = X * dN.transpose();
        // phi(j) = (j - 1)^2 + log((j - b) / (1 - b))^2, j = det J_q / J0_e.
        const double j = J.determinant() / straight_[k];
        if (!(j > b)) return INFINITY;
        const double l = std::log((j - b) / (1 - b));
        total += ((j - 1) * (j - 1) + l * l) / samples;
        if (!gradient) continue;
        // dj/dx_a = cof(J) dN_a / J0_e.
        const Eigen::Matrix3d C =
            ((2 * (j - 1) + 2 * l / (j - b)) / (samples * straight_[k])) * cofactor(J);
        for (Eigen::Index i = 0; i < local_.rows(); ++i) {
          const int a = local_(i, static_cast<Eigen::Index>(k));
          if (a >= 0) gradient->segment<3>(3 * a) += C * dN.col(i);
        }
      }
    }
    return total;
  }

 private:
  VolumeMesh& m_;
  const VolumeCad& cad_;
  const TetTabulation& tab_;
  std::vector<int> elements_;
  std::vector<int> nodes_;
  std::map<std::pair<int, int>, std::vector<int>> sliding_;
  Eigen::MatrixXi local_;  // element node -> movable node index, or -1
  Eigen::VectorXd start_;  // the movable nodes where the patch started
  std::vector<double> radius_;
  std::vector<double> straight_;
  std::vector<char> slides_;                // a node on CAD, moving in its plane or line
  std::vector<Eigen::Matrix3d> projector_;  // onto that plane or line (identity inside)  // J0_e:
                                            // det J of each element's corners, at the start
};

// L-BFGS with backtracking (Nocedal & Wright 2006, Alg 7.5), the iterate
// projected (Patch::place) after each trial step.
// `h` is the patch's typical edge length: the first step moves a node by at most h / 20.
void minimise(Patch& patch, double barrier, double h, int iterations) {
  Eigen::VectorXd z = patch.positions(), g, trial_g;
  double f = patch.energy(barrier, &g);
  std::deque<std::pair<Eigen::VectorXd, Eigen::VectorXd>> history;  // (s, y)
  for (int it = 0; it < iterations; ++it) {
    // Two-loop recursion for the direction.
    Eigen::VectorXd q = g;
    std::vector<double> alpha(history.size());
    for (int k = static_cast<int>(history.size()) - 1; k >= 0; --k) {
      const auto& [s, y] = history[k];
      alpha[k] = s.dot(q) / y.dot(s);
      q -= alpha[k] * y;
    }
    if (!history.empty()) {
      const auto& [s, y] = history.back();
      q *= s.dot(y) / y.dot(y);
    } else {
      const double gn = g.cwiseAbs().maxCoeff();
      if (gn == 0) return;
      q *= 0.05 * h / gn;
    }
    for (std::size_t k = 0; k < history.size(); ++k) {
      const auto& [s, y] = history[k];
      q += s * (alpha[k] - y.dot(q) / y.dot(s));
    }
    Eigen::VectorXd dir = -q;
    if (dir.dot(g) >= 0) dir = -g * (0.05 * h / std::max(1e-300, g.cwiseAbs().maxCoeff()));
    double step = 1;
    bool moved = false;
    for (int tries = 0; tries < 30; ++tries, step *= 0.5) {
      Eigen::VectorXd trial = z + step * dir;
      patch.place(trial);
      const double ft = patch.energy(barrier, &trial_g);
      if (std::isfinite(ft) && ft <= f + 1e-4 * step * g.dot(dir)) {
        const Eigen::VectorXd s = trial - z, y = trial_g - g;
        if (s.dot(y) > 1e-12 * s.norm() * y.norm()) {
          history.emplace_back(s, y);
          if (history.size() > 8) history.pop_front();
        }
        z = std::move(trial);
        g = trial_g;
        const double gain = f - ft;
        f = ft;
        moved = true;
        if (gain < 1e-10 * std::abs(f)) return;
        break;
      }
    }
    if (!moved) {
      Eigen::VectorXd back = z;
      patch.place(back);  // where it was
      return;
    }
  }
}

}  // namespace

VolumeOptimiseResult optimise_volume(VolumeMesh& m, const VolumeCad& cad, MeshValidity& validity,
                                     const VolumeOptimiseOptions& o) {
  VolumeOptimiseResult r;
  r.before = r.after = validity.worst;
  const int n = m.num_tetrahedra();
  std::vector<char> poor(static_cast<std::size_t>(n), 0);
  bool any = false;
  for (int e = 0; e < n; ++e)
    any |= (poor[e] = validity.ratio(e) < o.threshold && (o.only.empty() || o.only[e])) != 0;
  if (!any) return r;

  // What may move: inside the volume (its vertices if o.move_vertices), and on
  // CAD curves and surfaces all but the linear mesh's vertices.
  std::vector<char> vertex(static_cast<std::size_t>(m.num_nodes()), 0),
      movable(static_cast<std::size_t>(m.num_nodes()), 0);
  for (int e = 0; e < n; ++e)
    for (int i = 0; i < 4; ++i) vertex[m.tet(i, e)] = 1;
  std::map<std::pair<int, int>, bool> geometry;
  for (int i = 0; i < m.num_nodes(); ++i) {
    const VolumeNodeClass& c = m.node_class[i];
    if (c.dim == 3) {
      movable[i] = !vertex[i] || o.move_vertices;
    } else if ((c.dim == 1 || c.dim == 2) && (!vertex[i] || o.slide_vertices)) {
      auto [it, fresh] = geometry.try_emplace({c.dim, c.tag}, false);
      if (fresh) it->second = cad.has_geometry(c.dim, c.tag);
      movable[i] = it->second;
    }
  }

  const CornerTetrahedra at(m);
  std::vector<char> in = poor;
  grow_by_corners(m, at, o.rings, in);
  // Nodes of elements outside the patches are held.
  for (int e = 0; e < n; ++e)
    if (!in[e])
      for (Eigen::Index k = 0; k < m.tet.rows(); ++k) movable[m.tet(k, e)] = 0;

  // Patches: connected components of `in` through shared corners.
  const TetTabulation tab = lattice_sampling(m.order);
  std::vector<int> component(static_cast<std::size_t>(n), -1);
  for (int seed = 0; seed < n; ++seed) {
    if (!in[seed] || component[seed] >= 0) continue;
    std::vector<int> elements = {seed};
    component[seed] = seed;
    for (std::size_t k = 0; k < elements.size(); ++k)
      for (int i = 0; i < 4; ++i) {
        const int v = m.tet(i, elements[k]);
        for (int j = at.start[v]; j < at.start[v + 1]; ++j) {
          const int f = at.list[j];
          if (in[f] && component[f] < 0) {
            component[f] = seed;
            elements.push_back(f);
          }
        }
      }
    Patch patch(m, cad, tab, elements, movable);
    if (patch.empty()) continue;
    ++r.patches;
    const Patch::State saved = patch.state();
    double before = INFINITY;
    int invalid_before = 0;
    for (int e : elements) {
      before = std::min(before, validity.ratio(e));
      invalid_before += validity.min_det(e) > 0 ? 0 : 1;
    }
    // The moving barrier of Toulorge et al. (2013): each round's barrier just
    // below the lowest det J_q / mean_e, so a round never lowers it and raising
    // it lowers the energy; rounds while it rises.
    Patch::State on_cad = saved;
    for (int round = 0; round < o.rounds; ++round) {
      const double lo = patch.lowest_normalised();
      const double mean = patch.determinants().second;
      const double barrier = lo - 0.1 * std::max(std::abs(lo), 0.05);
      minimise(patch, barrier, std::cbrt(mean), o.iterations);
      if (!patch.snap()) {  // back to the last state on the CAD
        patch.restore(on_cad);
        break;
      }
      on_cad = patch.state();
      const double now = patch.lowest_normalised();
      if (now < lo + o.round_gain * std::max(std::abs(lo), 0.05)) break;
    }
    // Kept only if certified better: fewer invalid elements, or as many and a
    // better worst.
    std::vector<JacobianBounds> bounds;
    double after = INFINITY;
    int invalid_after = 0;
    for (int e : elements) {
      bounds.push_back(tetrahedron_jacobian_bounds(m.tetrahedron_nodes(e), m.order));
      after = std::min(after, scaled_jacobian_ratio(bounds.back()));
      invalid_after += bounds.back().valid_certified ? 0 : 1;
    }
    if (invalid_after > invalid_before || (invalid_after == invalid_before && !(after > before))) {
      patch.restore(saved);
      continue;
    }
    patch.update_parameters();
    ++r.accepted;
    for (std::size_t k = 0; k < elements.size(); ++k) {
      const int e = elements[k];
      validity.ratio(e) = scaled_jacobian_ratio(bounds[k]);
      validity.min_det(e) = bounds[k].min_lower;
      validity.converged[e] = bounds[k].converged;
    }
  }
  count_validity(validity);
  r.after = validity.worst;
  return r;
}

}  // namespace homesh
