#include "curving/optimise_mesh.h"

#include <omp.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "curving/deform_mesh.h"
#include "curving/optimisation_patches.h"
#include "curving/patch_newton.h"
#include "fem/element_tabulation.h"
#include "quality/ideal_jacobian.h"
#include "quality/mesh_validity.h"

namespace homesh {
namespace {

constexpr double kNodeArmijo = 1e-4;  // sufficient decrease of the backtracking
constexpr int kNodeMaxHalvings = 20;
constexpr double kNegligible = 1e-9;  // relative energy drop of a node move that counts
// Least work (sum over the patches' elements of their node count squared: a p = 5
// triangle's 441 is about 40 us of Hessian a Newton step) for the patches to be optimised
// in parallel: a fresh process's first thread team can cost 10-40 ms on a 2-core VM
// (fem/elasticity_assembler.cpp's kParallelWork says how that was measured).
constexpr double kParallelPatchWork = 30000;

// One patch being optimised on the shared coordinates x (its free nodes are its own).
class PatchOptimiser {
 public:
  // floor: the patch's worst certified minJ/maxJ at the start, which no step may
  // take an element below.
  PatchOptimiser(const Mesh& m, Eigen::Matrix2Xd& x, SlidingNodes& sliding,
                 const OptimisationPatch& patch, const ElementTabulation& tab,
                 const ElementTabulation& quad_tab, const OptimiseOptions& opt, double floor)
      : m_(m),
        x_(x),
        sliding_(sliding),
        patch_(patch),
        tab_(tab),
        quad_tab_(quad_tab),
        opt_(opt),
        floor_(floor) {
    const int ne = static_cast<int>(patch.elements.size());
    target_.resize(ne);
    energy_.resize(ne);
    for (int le = 0; le < ne; ++le) {
      const int e = patch.elements[le];
      if (e >= m.num_triangles()) {
        target_[le] = quad_target(m.quad.col(e - m.num_triangles()));
        continue;
      }
      Eigen::Matrix2d J_lin;
      J_lin.col(0) = x_.col(m.tri(1, e)) - x_.col(m.tri(0, e));
      J_lin.col(1) = x_.col(m.tri(2, e)) - x_.col(m.tri(0, e));
      // The straight-sided target needs a counter-clockwise straight element; a curved
      // element whose corners alone turn clockwise keeps the ideal target.
      target_[le] = opt.target == OptimiseOptions::Target::straight && J_lin.determinant() > 0
                        ? Eigen::Matrix2d(J_lin.inverse())
                        : ideal_jacobian(Eigen::Matrix2d::Identity());
    }
    // Element-local stars of the free nodes: (patch element, node slot in it); the free
    // nodes are ascending, so a node's place among them is a binary search (no #nodes
    // table per patch).
    const std::vector<int>& free = patch.free_nodes;
    star_.resize(free.size());
    visited_.assign(patch.free_nodes.size(), -1);
    changed_.assign(ne, 0);
    for (int le = 0; le < ne; ++le) {
      const auto nodes = element_node_indices(m, patch.elements[le]);
      for (int k = 0; k < nodes.size(); ++k) {
        const int node = nodes(k);
        const auto it = std::lower_bound(free.begin(), free.end(), node);
        if (it != free.end() && *it == node) star_[it - free.begin()].push_back({le, k});
      }
    }
  }

  const std::vector<Eigen::Matrix2d>& targets() const { return target_; }

  double total_energy() {
    double E = 0;
    for (int le = 0; le < static_cast<int>(energy_.size()); ++le)
      E += energy_[le] = element_energy(le, nullptr);
    return E;
  }

  // One node-by-node sweep; returns the patch energy after it. A node is visited only
  // if some element round it changed since its last visit (all of them in the first
  // sweep): converged regions of a large patch cost nothing.
  double sweep() {
    for (int i = 0; i < static_cast<int>(star_.size()); ++i) {
      bool stale = visited_[i] < 0;
      for (const Slot& s : star_[i]) stale = stale || changed_[s.element] > visited_[i];
      if (!stale) continue;
      visited_[i] = clock_;
      move_node(i);
    }
    double E = 0;
    for (double e : energy_) E += e;
    return E;
  }

 private:
  struct Slot {
    int element;  // index into patch.elements
    int node;     // node slot in the element
  };

  // Target inverse of a quadrilateral with node indices q: the unit square (W = J) for the
  // ideal target; for the straight one the inverse Jacobian at the centre of its bilinear
  // (corner) shape, which is its Jacobian everywhere for a parallelogram (so Theta_shape = 0
  // for a straight parallelogram whatever its aspect ratio), the unit square where that
  // turns clockwise.
  Eigen::Matrix2d quad_target(Eigen::MatrixXi::ConstColXpr q) const {
    if (opt_.target == OptimiseOptions::Target::straight) {
      const Eigen::Vector2d a = x_.col(q(0)), b = x_.col(q(1)), c = x_.col(q(2)), d = x_.col(q(3));
      Eigen::Matrix2d J_mid;
      J_mid.col(0) = 0.5 * (b + c - a - d);
      J_mid.col(1) = 0.5 * (c + d - a - b);
      if (J_mid.determinant() > 0) return J_mid.inverse();
    }
    return Eigen::Matrix2d::Identity();
  }

  // The nodes of patch element le, in a buffer reused by every call.
  const Eigen::Matrix2Xd& nodes(int le) const {
    const auto n = element_node_indices(m_, patch_.elements[le]);
    X_.resize(2, n.size());
    for (int k = 0; k < n.size(); ++k) X_.col(k) = x_.col(n(k));
    return X_;
  }

  // Energy of patch element le and, if asked, its gradient by the element's node slot `node`.
  double element_energy(int le, Eigen::Matrix2Xd* gradient, int node = -1) const {
    const ElementTabulation& tab = patch_.elements[le] < m_.num_triangles() ? tab_ : quad_tab_;
    return distortion_energy(nodes(le), tab, target_[le], opt_.energy, gradient, node);
  }

  // Energy of node i's star and its gradient by the node's position.
  double star_energy(int i, Eigen::Vector2d* g) const {
    double E = 0;
    if (g) g->setZero();
    for (const Slot& s : star_[i]) {
      E += element_energy(s.element, g ? &grad_ : nullptr, s.node);
      if (!std::isfinite(E)) return E;
      if (g) *g += grad_.col(s.node);
    }
    return E;
  }

  // Every element round node i certified valid with minJ/maxJ >= floor_.
  bool star_certified(int i) const {
    for (const Slot& s : star_[i]) {
      const JacobianBounds b =
          element_jacobian_bounds(m_, patch_.elements[s.element], nodes(s.element), opt_.bounds);
      if (!b.valid_certified || scaled_jacobian_ratio(b) < floor_) return false;
    }
    return true;
  }

  // Length scales of node i's star: the smallest height and the longest edge of the
  // straight elements through its elements' corners (element_lengths).
  std::pair<double, double> star_lengths(int i) const {
    double height = std::numeric_limits<double>::infinity(), longest = 0;
    for (const Slot& s : star_[i]) {
      const auto [h, edge] = element_lengths(m_, x_, patch_.elements[s.element]);
      height = std::min(height, h);
      longest = std::max(longest, edge);
    }
    return {height, longest};
  }

  // Accepts node i's new position if its star's energy E is finite, lowers E0 enough
  // (Armijo: by at least kNodeArmijo t |slope|) and every element round it is certified;
  // then updates the stored energies and wakes the neighbours.
  bool accept(int i, double E0, double t, double slope) {
    const double E = star_energy(i, nullptr);
    if (!(std::isfinite(E) && E < E0 + kNodeArmijo * t * slope && star_certified(i))) return false;
    // Moves that lower the star's energy by less than kNegligible of it do not
    // wake the neighbours.
    const bool moved = E0 - E > kNegligible * E0;
    if (moved) ++clock_;
    for (const Slot& s : star_[i]) {
      energy_[s.element] = element_energy(s.element, nullptr);
      if (moved) changed_[s.element] = clock_;
    }
    return true;
  }

  // C(u) of sliding node `node`'s curve, u kept in the range of an open curve and
  // wrapped into it for the evaluator on a closed one.
  Eigen::Vector2d on_curve(int node, double u, Eigen::Vector2d* tangent) const {
    return sliding_.curves->point(sliding_.tag(node), wrap_parameter(sliding_.range(node), u),
                                  tangent);
  }

  // Node i sliding: a Newton step in its curve parameter u, backtracked as move_node.
  void slide_node(int i) {
    const int node = patch_.free_nodes[i];
    const CurveRange& range = sliding_.range(node);
    const double u0 = sliding_.u(node);
    const Eigen::Vector2d x0 = x_.col(node);
    Eigen::Vector2d g, tangent;
    on_curve(node, u0, &tangent);
    const double E0 = star_energy(i, &g);
    const double speed = tangent.norm();
    if (!std::isfinite(E0) || speed == 0) return;
    const double gu = g.dot(tangent);
    if (gu == 0) return;
    const auto [height, longest] = star_lengths(i);
    // Second derivative by a forward difference of dE/du.
    const double h = 1e-6 * height / speed;
    Eigen::Vector2d gh, th;
    x_.col(node) = on_curve(node, u0 + h, &th);
    const double Eh = star_energy(i, &gh);
    x_.col(node) = x0;
    const double H = std::isfinite(Eh) ? (gh.dot(th) - gu) / h : 0;
    double du = H > 0 ? -gu / H : -std::copysign(height / speed, gu);
    const double cap = 0.5 * longest / speed;
    if (std::abs(du) > cap) du = std::copysign(cap, du);
    if (!range.closed) du = std::clamp(u0 + du, range.a, range.b) - u0;
    if (du == 0) return;
    const double slope = gu * du;
    double t = 1;
    for (int halving = 0; halving <= kNodeMaxHalvings; ++halving, t *= 0.5) {
      x_.col(node) = on_curve(node, u0 + t * du, nullptr);
      if (accept(i, E0, t, slope)) {
        sliding_.u(node) = u0 + t * du;
        return;
      }
    }
    x_.col(node) = x0;
  }

  // A modified Newton step on node i, backtracked; the node stays if nothing lowers
  // the energy with every element round it certified valid and no worse than the
  // patch's worst at the start (so a patch is reverted only by rounding).
  void move_node(int i) {
    const int node = patch_.free_nodes[i];
    if (sliding_.slides(node)) {
      slide_node(i);
      return;
    }
    const Eigen::Vector2d x0 = x_.col(node);
    Eigen::Vector2d g;
    const double E0 = star_energy(i, &g);
    if (!std::isfinite(E0) || g.squaredNorm() == 0) return;
    const auto [height, longest] = star_lengths(i);
    // Hessian by forward differences of the analytic gradient.
    const double h = 1e-6 * height;
    Eigen::Matrix2d H;
    for (int c = 0; c < 2; ++c) {
      x_.col(node) = x0;
      x_(c, node) += h;
      Eigen::Vector2d gc;
      const double Ec = star_energy(i, &gc);
      H.col(c) = std::isfinite(Ec) ? Eigen::Vector2d((gc - g) / h) : Eigen::Vector2d::Zero();
    }
    x_.col(node) = x0;
    H = 0.5 * (H + H.transpose()).eval();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(H);
    const Eigen::Vector2d lambda = eig.eigenvalues();
    Eigen::Vector2d dir;
    if (lambda(1) > 0) {
      const double floor = 1e-6 * lambda(1);
      const Eigen::Vector2d clamped = lambda.cwiseMax(floor);
      dir = -eig.eigenvectors() * (eig.eigenvectors().transpose() * g).cwiseQuotient(clamped);
    } else {
      dir = -g.normalized() * height;
    }
    const double cap = 0.5 * longest;
    if (dir.norm() > cap) dir *= cap / dir.norm();
    const double slope = g.dot(dir);
    double t = 1;
    for (int halving = 0; halving <= kNodeMaxHalvings; ++halving, t *= 0.5) {
      x_.col(node) = x0 + t * dir;
      if (accept(i, E0, t, slope)) return;
    }
    x_.col(node) = x0;
  }

  const Mesh& m_;
  Eigen::Matrix2Xd& x_;
  SlidingNodes& sliding_;
  const OptimisationPatch& patch_;
  const ElementTabulation& tab_;       // of the triangles
  const ElementTabulation& quad_tab_;  // of the quadrilaterals
  const OptimiseOptions& opt_;
  double floor_;
  std::vector<Eigen::Matrix2d> target_;
  std::vector<double> energy_;
  std::vector<std::vector<Slot>> star_;
  mutable Eigen::Matrix2Xd X_, grad_;  // buffers of nodes() and star_energy()
  // Move clock: changed_[element] is the clock of the last move in it, visited_[node]
  // the clock at the node's last visit (-1: never).
  long clock_ = 0;
  std::vector<long> changed_, visited_;
};

// Certified minJ/maxJ of 2D element e with nodes at x; -infinity unless certified valid.
double certified_ratio(const Mesh& m, const Eigen::Matrix2Xd& x, int e, const BoundsOptions& b) {
  const auto nodes = element_node_indices(m, e);
  Eigen::Matrix2Xd X(2, nodes.size());
  for (int k = 0; k < nodes.size(); ++k) X.col(k) = x.col(nodes(k));
  const JacobianBounds jb = element_jacobian_bounds(m, e, X, b);
  return jb.valid_certified ? scaled_jacobian_ratio(jb) : -std::numeric_limits<double>::infinity();
}

struct PatchOutcome {
  bool accepted = false;
  int sweeps = 0;
  int newton = 0;
  double energy_before = 0, energy_after = 0;
};

// One pass: patches of opt.layers rings round the poor elements (first_layers ignored).
OptimiseResult optimise_pass(const Mesh& m, const std::vector<bool>& fixed,
                             const OptimiseOptions& opt, const CurveEvaluator* curves,
                             const MeshValidity* known) {
  if (static_cast<int>(fixed.size()) != m.num_nodes())
    throw Error("optimise_mesh: fixed has " + std::to_string(fixed.size()) + " entries for " +
                std::to_string(m.num_nodes()) + " nodes");
  if (m.order < 1) throw Error("optimise_mesh: the mesh must be of order 1 or more");
  if (opt.layers < 0 || opt.max_sweeps < 0 || !(opt.tolerance >= 0) || !(opt.energy.r >= 1) ||
      !(opt.energy.alpha >= 0) || !(opt.energy.epsilon >= 0 && opt.energy.epsilon < 1))
    throw Error(
        "optimise_mesh: bad options (layers, max_sweeps >= 0, tolerance >= 0, r >= 1, "
        "alpha >= 0, 0 <= epsilon < 1)");

  OptimiseResult res;
  res.mesh = m;
  const MeshValidity before = mesh_validity(m, {&m, known}, opt.bounds);
  Eigen::VectorXd ratio = before.ratio;
  std::vector<bool> valid(m.num_elements_2d()), poor(m.num_elements_2d());
  for (int e = 0; e < m.num_elements_2d(); ++e) {
    valid[e] = before.min_det(e) > 0;
    poor[e] = valid[e] && ratio(e) < opt.threshold;
    res.poor_before += poor[e];
  }
  res.invalid = before.invalid;
  res.worst_before = before.worst;

  // Sliding: nodes on a curve the evaluator slides, not fixed by the caller, and not
  // vertices unless opt.slide says so.
  const std::vector<bool> vertex = vertex_nodes(m);
  SlidingNodes sliding;
  sliding.curves = curves;
  sliding.reset(m.num_nodes());
  if (curves && opt.slide != OptimiseOptions::Slide::none)
    for (int i = 0; i < m.num_nodes(); ++i) {
      const NodeClass& c = m.node_class[i];
      if (fixed[i] || c.dim != 1 || !curves->slides(c.tag)) continue;
      if (vertex[i] && opt.slide != OptimiseOptions::Slide::all) continue;
      sliding.add(i, c.tag, std::isfinite(c.u) ? c.u : curves->parameter(c.tag, m.x.col(i)),
                  curves->range(c.tag));
    }
  // Held: the caller's nodes, the boundary nodes that do not slide, every node of an
  // element not certified valid (no untangling: the barrier needs a valid start; such
  // an element ends up in no patch, and the patches round it still move), and the
  // vertices that do not slide unless free_vertices.
  std::vector<bool> held = fixed;
  const std::vector<bool> boundary = boundary_nodes(m);
  for (int i = 0; i < m.num_nodes(); ++i)
    held[i] = held[i] || (!sliding.slides(i) && (boundary[i] || (vertex[i] && !opt.free_vertices)));
  for (int e = 0; e < m.num_elements_2d(); ++e)
    if (!valid[e])
      for (int i : element_node_indices(m, e)) held[i] = true;
  const std::vector<OptimisationPatch> patches = optimisation_patches(m, poor, opt.layers, held);
  res.patches = static_cast<int>(patches.size());
  // The worst valid element outside every patch, at least the threshold: once a patch's
  // moved elements all reach it, its steps cannot raise the mesh's worst (patch_newton's
  // `enough`; Gmsh's optimiser stops at its target, which here is where the rest of the
  // mesh stands).
  double enough = std::numeric_limits<double>::infinity();
  {
    std::vector<bool> in_patch(m.num_elements_2d(), false);
    for (const OptimisationPatch& patch : patches)
      for (int e : patch.elements) in_patch[e] = true;
    for (int e = 0; e < m.num_elements_2d(); ++e)
      if (!in_patch[e] && valid[e]) enough = std::min(enough, ratio(e));
    enough = std::max(enough, opt.threshold);
  }
  // The lattice of order 2 (p - 1) where a triangle's det J has its Bezier coefficients is
  // a single point at p = 1 (det J constant): no lattice there.
  const int degree = opt.quadrature_degree > 0 ? opt.quadrature_degree : 2 * m.order;
  const ElementTabulation tab =
      tabulate_element_and_lattice(m.order, degree, m.order > 1 ? opt.lattice_weight : 0.0);
  const ElementTabulation quad_tab =
      m.num_quads() > 0 ? tabulate_quad_element_and_lattice(m.order, degree, opt.lattice_weight)
                        : ElementTabulation{};

  Eigen::Matrix2Xd& x = res.mesh.x;
  std::vector<PatchOutcome> outcome(patches.size());
  // One thread per core (or opt.threads), not OpenMP's default: a Gmsh-API script's
  // gmsh.initialize sets that to General.NumThreads, 1 unless the user says otherwise, for
  // the whole process. Over the patches, where their elements' work (sum of n^2) is worth
  // a team: a fresh process starts its threads (circle_nolayer_coarse p = 2 took 1.27x
  // with 2 threads for its 3 small patches). One patch's element loops in parallel as well
  // (energies, Hessians, certificates) gained nothing: plate_holes_nolayer_coarse p = 4
  // 1.26x as long with them in place of the patches in parallel, a lone patch's the same.
  const int cores = std::max(1, opt.threads > 0 ? opt.threads : omp_get_num_procs());
  double work = 0;
  for (const OptimisationPatch& patch : patches)
    for (int e : patch.elements) {
      const double n = double(element_node_indices(m, e).size());
      work += n * n;
    }
  const int threads = patches.size() > 1 && work >= kParallelPatchWork
                          ? std::min<int>(cores, int(patches.size()))
                          : 1;
#pragma omp parallel for schedule(dynamic) num_threads(threads) if (threads > 1)
  for (int k = 0; k < static_cast<int>(patches.size()); ++k) {
    const OptimisationPatch& patch = patches[k];
    double worst = std::numeric_limits<double>::infinity();
    bool all_valid = true;
    for (int e : patch.elements) {
      all_valid = all_valid && valid[e];
      worst = std::min(worst, ratio(e));
    }
    if (!all_valid) continue;  // cannot happen (their nodes are held), kept as a guard
    Eigen::Matrix2Xd start(2, patch.free_nodes.size());
    std::vector<double> start_u(patch.free_nodes.size());
    for (int i = 0; i < start.cols(); ++i) {
      start.col(i) = x.col(patch.free_nodes[i]);
      start_u[i] = sliding.slides(patch.free_nodes[i]) ? sliding.u(patch.free_nodes[i]) : 0.0;
    }
    PatchOptimiser po(m, x, sliding, patch, tab, quad_tab, opt, worst);
    PatchOutcome& o = outcome[k];
    o.energy_before = po.total_energy();
    if (opt.newton_iterations > 0) {
      PatchProblem problem;
      problem.mesh = &m;
      problem.elements = &patch.elements;
      problem.free_nodes = &patch.free_nodes;
      problem.targets = &po.targets();
      problem.tab = &tab;
      problem.quad_tab = &quad_tab;
      problem.energy = opt.energy;
      problem.bounds = opt.bounds;
      problem.floor = worst;
      problem.enough = opt.until == OptimiseOptions::Until::rest
                           ? enough
                           : std::numeric_limits<double>::infinity();
      o.newton =
          patch_newton(problem, x, sliding, opt.newton_iterations, opt.newton_tolerance).iterations;
    }
    double E = po.total_energy();
    while (o.sweeps < opt.max_sweeps) {
      const double next = po.sweep();
      ++o.sweeps;
      const bool done = !(E - next > opt.tolerance * E);
      E = next;
      if (done) break;
    }
    o.energy_after = E;
    // Certificate: every element valid and the patch's worst minJ/maxJ not lowered.
    std::vector<double> after(patch.elements.size());
    double worst_after = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < patch.elements.size(); ++j) {
      after[j] = certified_ratio(m, x, patch.elements[j], opt.bounds);
      worst_after = std::min(worst_after, after[j]);
    }
    o.accepted = worst_after >= worst;
    if (o.accepted) {
      for (std::size_t j = 0; j < patch.elements.size(); ++j) ratio(patch.elements[j]) = after[j];
    } else {
      for (int i = 0; i < start.cols(); ++i) {
        x.col(patch.free_nodes[i]) = start.col(i);
        if (sliding.slides(patch.free_nodes[i])) sliding.u(patch.free_nodes[i]) = start_u[i];
      }
    }
  }

  for (std::size_t k = 0; k < patches.size(); ++k) {
    const PatchOutcome& o = outcome[k];
    res.sweeps += o.sweeps;
    res.newton_steps += o.newton;
    if (!o.accepted) continue;
    ++res.accepted;
    res.moved_nodes += static_cast<int>(patches[k].free_nodes.size());
    for (int i : patches[k].free_nodes) {
      if (!sliding.slides(i)) continue;
      ++res.sliding_nodes;
      res.mesh.node_class[i].u = wrap_parameter(sliding.range(i), sliding.u(i));
    }
    res.energy_before += o.energy_before;
    res.energy_after += o.energy_after;
  }
  // Over every 2D element: a caller holding the quadrilaterals' nodes gets them counted.
  res.worst_after = m.num_elements_2d() > 0 ? ratio.minCoeff() : 1.0;
  for (int e = 0; e < m.num_elements_2d(); ++e)
    res.poor_after += before.min_det(e) > 0 && ratio(e) < opt.threshold;
  // The kept patches' elements bounded again, the others as they were.
  res.validity = mesh_validity(res.mesh, m, before, opt.bounds);
  return res;
}

}  // namespace

OptimiseResult optimise_mesh(const Mesh& m, const std::vector<bool>& fixed,
                             const OptimiseOptions& opt, const CurveEvaluator* curves,
                             const MeshValidity* known) {
  if (opt.first_layers < 0) throw Error("optimise_mesh: bad options (first_layers >= 0)");
  if (opt.first_layers == 0 || opt.first_layers >= opt.layers)
    return optimise_pass(m, fixed, opt, curves, known);
  OptimiseOptions small = opt;
  small.layers = opt.first_layers;
  OptimiseResult first = optimise_pass(m, fixed, small, curves, known);
  if (first.poor_after == 0) return first;
  OptimiseResult r = optimise_pass(first.mesh, fixed, opt, curves, &first.validity);
  r.worst_before = first.worst_before;
  r.poor_before = first.poor_before;
  r.invalid = first.invalid;
  r.patches += first.patches;
  r.accepted += first.accepted;
  r.sweeps += first.sweeps;
  r.newton_steps += first.newton_steps;
  r.moved_nodes += first.moved_nodes;
  r.sliding_nodes += first.sliding_nodes;
  r.energy_before += first.energy_before;
  r.energy_after += first.energy_after;
  return r;
}

}  // namespace homesh
