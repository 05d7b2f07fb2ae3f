#include "curving/patch_newton.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "curving/optimisation_patches.h"
#include "fem/amd_ldlt.h"
#include "fem/sparse_pattern.h"

namespace homesh {
namespace {

constexpr double kArmijo = 1e-4;  // sufficient decrease of the backtracking
constexpr int kMaxHalvings = 12;  // of one step's length
constexpr int kMaxDampings = 8;   // raises of lambda (x 10) before giving up
constexpr double kFirstDamping = 1e-4;
constexpr double kLeastDamping = 1e-8;  // below this after accepted steps: pure Newton

// The symmetric matrix H with its negative eigenvalues set to 0.
Eigen::MatrixXd positive_part(const Eigen::MatrixXd& H) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(H);
  return eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).asDiagonal() *
         eig.eigenvectors().transpose();
}

class PatchNewton {
 public:
  PatchNewton(const PatchProblem& p, Eigen::Matrix2Xd& x, SlidingNodes& s)
      : p_(p), m_(*p.mesh), elements_(*p.elements), free_(*p.free_nodes), x_(x), s_(s) {
    const int nf = static_cast<int>(free_.size());
    first_.assign(nf + 1, 0);
    for (int i = 0; i < nf; ++i) first_[i + 1] = first_[i] + (sliding(i) ? 1 : 2);
    slot_free_.resize(elements_.size());
    slot_nodes_.resize(elements_.size());
    for (std::size_t le = 0; le < elements_.size(); ++le) {
      const auto nodes = element_node_indices(m_, elements_[le]);
      for (int k = 0; k < nodes.size(); ++k) {
        const int node = nodes(k);
        const auto it = std::lower_bound(free_.begin(), free_.end(), node);
        if (it != free_.end() && *it == node) {
          slot_nodes_[le].push_back(k);
          slot_free_[le].push_back(static_cast<int>(it - free_.begin()));
        }
      }
    }
    // The Hessian's lower pattern: the dofs of two free slots of one element couple.
    const int n = dofs();
    std::vector<std::vector<int>> rows(n);
    for (const std::vector<int>& slots : slot_free_)
      for (const int a : slots)
        for (const int b : slots)
          for (int i = first_[b]; i < first_[b + 1]; ++i)
            for (int j = first_[a]; j < first_[a + 1]; ++j)
              if (i >= j) rows[j].push_back(i);
    SparsePattern pattern;
    pattern.outer.assign(n + 1, 0);
    for (int j = 0; j < n; ++j) {
      std::sort(rows[j].begin(), rows[j].end());
      rows[j].erase(std::unique(rows[j].begin(), rows[j].end()), rows[j].end());
      pattern.inner.insert(pattern.inner.end(), rows[j].begin(), rows[j].end());
      pattern.outer[j + 1] = static_cast<int>(pattern.inner.size());
    }
    pattern.assign_zero(H_);
    // Where each element's Hessian entries land in H_'s values, in assemble()'s order
    // (-1: above the diagonal, the mirror of one below): a search of the pattern per entry
    // took a fifth of the optimiser's assembly at p = 5.
    const int* outer = H_.outerIndexPtr();
    const int* inner = H_.innerIndexPtr();
    auto slot = [&](int row, int col) {
      if (row < col) return -1;
      return static_cast<int>(std::lower_bound(inner + outer[col], inner + outer[col + 1], row) -
                              inner);
    };
    scatter_.resize(elements_.size());
    for (std::size_t le = 0; le < elements_.size(); ++le) {
      const std::vector<int>& slots = slot_free_[le];
      std::vector<int>& to = scatter_[le];
      for (const int fa : slots)
        for (const int fb : slots)
          for (int i = first_[fb]; i < first_[fb + 1]; ++i)
            for (int j = first_[fa]; j < first_[fa + 1]; ++j) to.push_back(slot(i, j));
    }
  }

  // The lower triangle of the Hessian (its pattern fixed; each column starts at its
  // diagonal), filled by assemble().
  const Eigen::SparseMatrix<double>& hessian() const { return H_; }

  int dofs() const { return first_.back(); }

  // Summed energy of the elements with a free node (+infinity if any is inverted).
  double energy() {
    double E = 0;
    for (std::size_t le = 0; le < elements_.size(); ++le) {
      if (slot_free_[le].empty()) continue;
      E += distortion_energy(gather(le), tab(le), (*p_.targets)[le], p_.energy);
      if (!std::isfinite(E)) return E;
    }
    return E;
  }

  // Gradient g and Hessian (hessian(), by the dofs) of energy() at the current nodes.
  void assemble(Eigen::VectorXd& g) {
    const int nf = static_cast<int>(free_.size());
    std::vector<Eigen::Vector2d> tangent(nf);
    for (int i = 0; i < nf; ++i)
      if (sliding(i)) s_.point(free_[i], s_.u(free_[i]), &tangent[i]);
    g.setZero(dofs());
    std::fill_n(H_.valuePtr(), H_.nonZeros(), 0.0);
    double* value = H_.valuePtr();
    Eigen::Matrix2Xd G;
    Eigen::MatrixXd Hl;
    for (std::size_t le = 0; le < elements_.size(); ++le) {
      const std::vector<int>& slots = slot_free_[le];
      const int L = static_cast<int>(slots.size());
      if (L == 0) continue;
      Eigen::Matrix2Xd X = gather(le);
      const Eigen::Matrix2d& T = (*p_.targets)[le];
      const ElementTabulation& et = tab(le);
      // The element's exact gradient and Hessian by its free slots' nodes; a
      // quadrilateral's Hessian projected onto the positive semi-definite matrices (see the
      // header).
      distortion_energy_hessian(X, et, T, p_.energy, G, Hl, &slot_nodes_[le]);
      if (elements_[le] >= m_.num_triangles()) Hl = positive_part(0.5 * (Hl + Hl.transpose()));
      // To the dofs: a free node's (x, y) as they are, a sliding node's by its tangent
      // (d/du = C'(u) . d/dx); entries in scatter_'s order (rows of node b's dofs, then
      // columns of node a's).
      const int* to = scatter_[le].data();
      auto add = [&](double v) {
        if (*to >= 0) value[*to] += v;
        ++to;
      };
      for (int a = 0; a < L; ++a) {
        const int fa = slots[a], da = first_[fa];
        const Eigen::Vector2d ga = G.col(a);
        if (sliding(fa)) {
          g(da) += tangent[fa].dot(ga);
        } else {
          g(da) += ga(0);
          g(da + 1) += ga(1);
        }
        for (int b = 0; b < L; ++b) {
          const int fb = slots[b];
          const Eigen::Matrix2d h = Hl.block<2, 2>(2 * b, 2 * a);  // rows b, columns a
          if (sliding(fa) && sliding(fb)) {
            add(tangent[fb].dot(h * tangent[fa]));
          } else if (sliding(fa)) {
            const Eigen::Vector2d c = h * tangent[fa];
            add(c(0));
            add(c(1));
          } else if (sliding(fb)) {
            const Eigen::RowVector2d c = tangent[fb].transpose() * h;
            add(c(0));
            add(c(1));
          } else {
            for (int i = 0; i < 2; ++i)
              for (int j = 0; j < 2; ++j) add(h(i, j));
          }
        }
      }
    }
  }

  // Every element with a free node certified valid with minJ/maxJ >= floor; `least`
  // receives the smallest of their minJ/maxJ if they are.
  bool certified(double& least) {
    least = std::numeric_limits<double>::infinity();
    for (std::size_t le = 0; le < elements_.size(); ++le) {
      if (slot_free_[le].empty()) continue;
      const JacobianBounds b = element_jacobian_bounds(m_, elements_[le], gather(le), p_.bounds);
      if (!b.valid_certified) return false;
      const double ratio = scaled_jacobian_ratio(b);
      if (ratio < p_.floor) return false;
      least = std::min(least, ratio);
    }
    return true;
  }

  // Saves the free nodes (positions, parameters) as the base of move().
  void save() {
    x0_.resize(2, free_.size());
    u0_.resize(free_.size());
    for (std::size_t i = 0; i < free_.size(); ++i) {
      x0_.col(i) = x_.col(free_[i]);
      u0_[i] = sliding(i) ? s_.u(free_[i]) : 0.0;
    }
  }

  // The free nodes at the saved base plus t * step (sliding nodes by parameter).
  void move(const Eigen::VectorXd& step, double t) {
    for (std::size_t i = 0; i < free_.size(); ++i) {
      const int node = free_[i];
      if (t == 0) {
        x_.col(node) = x0_.col(i);
        if (sliding(i)) s_.u(node) = u0_[i];
      } else if (sliding(i)) {
        const CurveRange& r = s_.range(node);
        double u = u0_[i] + t * step(first_[i]);
        if (!r.closed) u = std::clamp(u, r.a, r.b);
        s_.u(node) = u;
        x_.col(node) = s_.point(node, u);
      } else {
        x_.col(node) = x0_.col(i) + t * step.segment<2>(first_[i]);
      }
    }
  }

 private:
  bool sliding(int i) const { return s_.slides(free_[i]); }

  const Eigen::Matrix2Xd& gather(std::size_t le) {
    const auto nodes = element_node_indices(m_, elements_[le]);
    X_.resize(2, nodes.size());
    for (int k = 0; k < nodes.size(); ++k) X_.col(k) = x_.col(nodes(k));
    return X_;
  }

  const ElementTabulation& tab(std::size_t le) const {
    return elements_[le] < m_.num_triangles() ? *p_.tab : *p_.quad_tab;
  }

  const PatchProblem& p_;
  const Mesh& m_;
  const std::vector<int>& elements_;
  const std::vector<int>& free_;
  Eigen::Matrix2Xd& x_;
  SlidingNodes& s_;
  std::vector<int> first_;  // dofs of free node i: first_[i] .. first_[i + 1] - 1
  // Per element, its free slots: their place in the element's nodes, and in free_.
  std::vector<std::vector<int>> slot_nodes_, slot_free_;
  std::vector<std::vector<int>> scatter_;  // per element, its Hessian entries' places in H_
  Eigen::Matrix2Xd X_, x0_;
  std::vector<double> u0_;
  Eigen::SparseMatrix<double> H_;
};

}  // namespace

JacobianBounds element_jacobian_bounds(const Mesh& m, int e, const Eigen::Matrix2Xd& X,
                                       const BoundsOptions& opt) {
  return e < m.num_triangles() ? jacobian_bounds(X, m.order, opt)
                               : quad_jacobian_bounds(X, m.order, opt);
}

PatchNewtonResult patch_newton(const PatchProblem& problem, Eigen::Matrix2Xd& x,
                               SlidingNodes& sliding, int max_iterations, double tolerance) {
  PatchNewton pn(problem, x, sliding);
  PatchNewtonResult res;
  double E = res.energy_before = res.energy_after = pn.energy();
  if (!std::isfinite(E) || pn.dofs() == 0) return res;
  double lambda = 0;
  Eigen::VectorXd g, step;
  const Eigen::SparseMatrix<double>& H = pn.hessian();
  Eigen::SparseMatrix<double> A = H;  // H damped; the same pattern
  const int* outer = H.outerIndexPtr();
  AmdLdlt ldlt;
  ldlt.analyze(H);
  while (res.iterations < max_iterations) {
    pn.assemble(g);
    Eigen::VectorXd d(H.rows());
    for (Eigen::Index i = 0; i < d.size(); ++i) d(i) = std::abs(H.valuePtr()[outer[i]]);
    const double dmax = d.maxCoeff();
    if (!(dmax > 0)) break;
    d = d.cwiseMax(1e-12 * dmax);
    pn.save();
    bool accepted = false, raised = false;
    double E_new = E, decrement = 0, least = 0;
    for (int damping = 0; damping <= kMaxDampings && !accepted; ++damping) {
      std::copy_n(H.valuePtr(), H.nonZeros(), A.valuePtr());
      for (Eigen::Index i = 0; i < A.rows(); ++i) A.valuePtr()[outer[i]] += lambda * d(i);
      if (ldlt.try_factorize(A)) {
        step = ldlt.solve(-g);
        const double slope = g.dot(step);
        decrement = -slope;
        if (slope < 0 && step.allFinite()) {
          double t = 1;
          for (int halving = 0; halving <= kMaxHalvings; ++halving, t *= 0.5) {
            pn.move(step, t);
            E_new = pn.energy();
            if (std::isfinite(E_new) && E_new < E + kArmijo * t * slope && pn.certified(least)) {
              accepted = true;
              break;
            }
          }
          if (!accepted) pn.move(step, 0);
        }
      }
      if (!accepted) {
        lambda = std::max(10 * lambda, kFirstDamping);
        raised = true;
      }
    }
    if (!accepted) break;
    ++res.iterations;
    // Lowered only after a step the first damping tried gave: where the Hessian is
    // indefinite, the lambda that made it definite is kept (no factorisation wasted).
    if (!raised) lambda = lambda / 10 < kLeastDamping ? 0 : lambda / 10;
    // Converged when the step's predicted decrease (the Newton decrement -g.d) is below
    // tolerance: a small actual decrease alone also happens on the way (a step cut short
    // by the barrier before the energy falls by orders of magnitude).
    // Also done when every moved element is at least `enough`: the mesh's worst is then
    // outside the patch, and further steps only raise the patch's better elements.
    const bool converged = !(decrement > tolerance * E) || least >= problem.enough;
    E = E_new;
    if (converged) break;
  }
  res.energy_after = E;
  return res;
}

}  // namespace homesh
