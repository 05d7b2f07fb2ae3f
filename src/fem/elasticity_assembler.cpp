#include "fem/elasticity_assembler.h"

#include <omp.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "core/error.h"
#include "fem/element_geometry.h"
#include "fem/element_load.h"
#include "fem/element_stiffness.h"

namespace homesh {

// Per-thread workspace of the element loop.
struct ElasticityAssembler::Workspace {
  Eigen::Matrix2Xd X;
  ElementGeometry geometry;
  Eigen::VectorXd lambda, mu, fe;
  Eigen::Matrix2Xd f;
  Eigen::Matrix3Xd sigma_t;
  Eigen::MatrixXd Ke, scratch;
  std::vector<int> dof, order;
  // Static condensation: the element's condensed (c) and kept (r) local dofs, the
  // blocks of Ke, K_cc's factor, and the condensed matrix, load and global dofs.
  std::vector<int> c, r;
  Eigen::MatrixXd Kcc, Kcr, S;
  Eigen::VectorXd fc, fr;
  Eigen::LLT<Eigen::MatrixXd> llt;
  std::vector<int> rdof;
};

namespace {

// The nodes of every 2D element (triangles, then quadrilaterals), CSR.
struct ElementNodes {
  std::vector<int> start{0}, node;
  int size() const { return int(start.size()) - 1; }
};

void append(ElementNodes& en, const Eigen::MatrixXi& elements) {
  for (Eigen::Index e = 0; e < elements.cols(); ++e) {
    for (Eigen::Index i = 0; i < elements.rows(); ++i) en.node.push_back(elements(i, e));
    en.start.push_back(int(en.node.size()));
  }
}

// Elements incident to each node, as offsets into a flat list (CSR).
struct Incidence {
  std::vector<int> start, element;
};

Incidence node_elements(const ElementNodes& en, int num_nodes) {
  Incidence inc;
  inc.start.assign(num_nodes + 1, 0);
  for (int node : en.node) ++inc.start[node + 1];
  std::partial_sum(inc.start.begin(), inc.start.end(), inc.start.begin());
  inc.element.resize(en.node.size());
  std::vector<int> next(inc.start.begin(), inc.start.end() - 1);
  for (int e = 0; e < en.size(); ++e)
    for (int k = en.start[e]; k < en.start[e + 1]; ++k) inc.element[next[en.node[k]]++] = e;
  return inc;
}

// Greedy colouring: each element takes the smallest colour none of the
// elements sharing one of its nodes has taken.
std::vector<std::vector<int>> colour_elements(const ElementNodes& en, const Incidence& inc) {
  std::vector<int> colour(en.size(), -1), stamp;
  std::vector<std::vector<int>> classes;
  for (int e = 0; e < en.size(); ++e) {
    for (int i = en.start[e]; i < en.start[e + 1]; ++i)
      for (int k = inc.start[en.node[i]]; k < inc.start[en.node[i] + 1]; ++k) {
        const int c = colour[inc.element[k]];
        if (c >= 0) stamp[c] = e;
      }
    int c = 0;
    while (c < int(stamp.size()) && stamp[c] == e) ++c;
    if (c == int(stamp.size())) {
      stamp.push_back(-1);
      classes.emplace_back();
    }
    colour[e] = c;
    classes[c].push_back(e);
  }
  return classes;
}

// Sorted neighbours (nodes sharing an element, itself excluded) of every node, CSR:
// node i's at node[start[i]] .. node[start[i + 1] - 1]. One array sized once: a vector
// per node, grown by push_back, made the p = 5 polish solve's pattern 5.3 ms of
// malloc churn in a fresh process (2.2 ms once its chunks were recycled).
struct Neighbours {
  std::vector<int> start, node;
};

Neighbours node_neighbours(const ElementNodes& en, const Incidence& inc) {
  const int num_nodes = int(inc.start.size()) - 1;
  Neighbours out;
  out.start.assign(num_nodes + 1, 0);
  std::vector<int> stamp(num_nodes, -1);
  // Each node's neighbours visited once, by a stamp: counted, then written.
  auto visit = [&](int i, int pass, auto&& take) {
    stamp[i] = 2 * i + pass;
    for (int k = inc.start[i]; k < inc.start[i + 1]; ++k) {
      const int e = inc.element[k];
      for (int a = en.start[e]; a < en.start[e + 1]; ++a) {
        const int j = en.node[a];
        if (stamp[j] != 2 * i + pass) {
          stamp[j] = 2 * i + pass;
          take(j);
        }
      }
    }
  };
  for (int i = 0; i < num_nodes; ++i) {
    int count = 0;
    visit(i, 0, [&](int) { ++count; });
    out.start[i + 1] = out.start[i] + count;
  }
  std::fill(stamp.begin(), stamp.end(), -1);
  out.node.resize(std::size_t(out.start[num_nodes]));
  for (int i = 0; i < num_nodes; ++i) {
    int next = out.start[i];
    visit(i, 1, [&](int j) { out.node[std::size_t(next++)] = j; });
    std::sort(out.node.begin() + out.start[i], out.node.begin() + out.start[i + 1]);
  }
  return out;
}

// Dof 2 node + component. Lower: every diagonal, and (r, c), r > c, for free
// dofs r, c of nodes sharing an element. Coupling: (r, c), r free, c fixed. A
// condensed node's dofs (per node) have their diagonal only and couple with none.
void dof_patterns(const Neighbours& neighbours, const std::vector<char>& fixed,
                  const std::vector<char>& condensed, SparsePattern& lower,
                  SparsePattern& coupling) {
  const int num_dofs = int(fixed.size());
  std::vector<int> outer(num_dofs + 1, 0), inner, c_outer(num_dofs + 1, 0), c_inner;
  // Two passes: the sizes counted, then the indices written into arrays of that size.
  for (int pass = 0; pass < 2; ++pass) {
    std::size_t n_inner = 0, n_coupling = 0;
    auto push = [&](int row) {
      if (pass == 1) inner[n_inner] = row;
      ++n_inner;
    };
    auto push_coupling = [&](int row) {
      if (pass == 1) c_inner[n_coupling] = row;
      ++n_coupling;
    };
    for (int i = 0; i < num_dofs / 2; ++i) {
      const auto first = neighbours.node.begin() + neighbours.start[i];
      const auto last = neighbours.node.begin() + neighbours.start[i + 1];
      for (int comp = 0; comp < 2; ++comp) {
        const int col = 2 * i + comp, other = 2 * i + 1 - comp;
        push(col);
        if (condensed[i]) {
          // The row u = 0 until recovered.
        } else if (!fixed[col]) {
          if (comp == 0 && !fixed[other]) push(other);
          for (auto it = first; it != last; ++it)
            for (int rc = 0, j = *it; rc < 2; ++rc)
              if (j > i && !condensed[j] && !fixed[2 * j + rc]) push(2 * j + rc);
        } else {
          bool own = !fixed[other];
          for (auto it = first; it != last; ++it) {
            const int j = *it;
            if (own && j > i) {
              push_coupling(other);
              own = false;
            }
            if (condensed[j]) continue;
            for (int rc = 0; rc < 2; ++rc)
              if (!fixed[2 * j + rc]) push_coupling(2 * j + rc);
          }
          if (own) push_coupling(other);
        }
        outer[col + 1] = int(n_inner);
        c_outer[col + 1] = int(n_coupling);
      }
    }
    if (pass == 0) {
      inner.resize(n_inner);
      c_inner.resize(n_coupling);
    }
  }
  lower = {std::move(outer), std::move(inner)};
  coupling = {std::move(c_outer), std::move(c_inner)};
}

// Lame's constants, body force and thermal stress (xx, yy, xy) at the points.
void evaluate(const ElasticityCoefficients& c, int e, ElasticityAssembler::Workspace& w) {
  const Eigen::Index nq = w.geometry.x.cols();
  w.lambda.resize(nq);
  w.mu.resize(nq);
  w.f.resize(2, nq);
  w.sigma_t.resize(3, nq);
  for (Eigen::Index q = 0; q < nq; ++q) {
    const QuadraturePoint point{e, static_cast<int>(q), w.geometry.x.col(q)};
    const Lame lame = lame_plane_strain(c.young(point), c.poisson(point));
    w.lambda(q) = lame.lambda;
    w.mu(q) = lame.mu;
    w.f.col(q) = c.body_force(point);
    const double s = c.beta(point) * (c.temperature(point) - c.reference_temperature);  // Eq 4.5
    const Eigen::Matrix2d S = c.anisotropic_stress(point);
    w.sigma_t.col(q) << s + S(0, 0), s + S(1, 1), 0.5 * (S(0, 1) + S(1, 0));
  }
}

}  // namespace

ElasticityAssembler::ElasticityAssembler(const Mesh& m, const std::vector<int>& fixed_dofs,
                                         const AssemblyOptions& options) {
  if (m.tri.rows() != triangle_node_count(m.order) && m.num_triangles() > 0)
    throw Error("assemble_elasticity: " + std::to_string(m.tri.rows()) +
                " nodes per triangle for order " + std::to_string(m.order));
  if (m.quad.rows() != quad_node_count(m.order) && m.num_quads() > 0)
    throw Error("assemble_elasticity: " + std::to_string(m.quad.rows()) +
                " nodes per quadrilateral for order " + std::to_string(m.order));
  Kind& triangles = kinds_[0];
  triangles.nodes = m.tri;
  triangles.tab =
      tabulate_element(m.order, stiffness_quadrature_degree(m.order, options.quadrature_margin));
  num_triangles_ = m.num_triangles();
  if (m.num_quads() > 0) {
    Kind& quads = kinds_[1];
    quads.nodes = m.quad;
    quads.tab = tabulate_quad_element(
        m.order, quad_stiffness_quadrature_degree(m.order, options.quadrature_margin));
  }
  const int num_nodes = m.num_nodes();
  fixed_.assign(2 * num_nodes, 0);
  for (int j : fixed_dofs) {
    if (j < 0 || j >= 2 * num_nodes)
      throw Error("apply_dirichlet: dof " + std::to_string(j) + " out of range 0.." +
                  std::to_string(2 * num_nodes - 1));
    fixed_[j] = 1;
  }
  ElementNodes en;
  for (const Kind& kind : kinds_) append(en, kind.nodes);
  for (int node : en.node)
    if (node < 0 || node >= num_nodes)
      throw Error("assemble_elasticity: node " + std::to_string(node) + " out of range 0.." +
                  std::to_string(num_nodes - 1));
  used_.assign(num_nodes, 0);
  for (int node : en.node) used_[node] = 1;
  const Incidence inc = node_elements(en, num_nodes);
  condensed_.assign(num_nodes, 0);
  if (options.condense)
    for (int i = 0; i < num_nodes; ++i)
      if (inc.start[i + 1] - inc.start[i] == 1 && !fixed_[2 * i] && !fixed_[2 * i + 1]) {
        condensed_[i] = 1;
        num_condensed_ += 2;
      }
  recovery_start_.assign(en.size() + 1, 0);
  for (int e = 0; e < en.size(); ++e) {
    int c = 0;
    for (int k = en.start[e]; k < en.start[e + 1]; ++k) c += condensed_[en.node[k]] ? 2 : 0;
    const int r = 2 * (en.start[e + 1] - en.start[e]) - c;
    recovery_start_[e + 1] = recovery_start_[e] + Eigen::Index(c) * (r + 1);
  }
  // Threads where the elements' work (sum of n^2: a p = 5 triangle's 441 takes some 15 us
  // to assemble) is worth starting a team in a fresh process: 150000, some 5 ms. A fresh
  // process's first team took 10-40 ms more in one run of three or four on this 2-core VM
  // (lshape_r02_nolayer p = 4, work 29k: 1.6-2.2 ms or 8.8-24.5 ms threaded, 1.6-3.5 ms
  // alone; work 73k and 92k: 14 and 40 ms against 5-6 alone), and its spinning worker slowed
  // the factorisation after it (29k: 2.8-4.3 ms against 1.0-3.2); from 237k on, two threads
  // won (6-7 against 12-15 ms; 1.36M: 53-69 against 81-110). Medians of 6 alternated fresh
  // runs, this and the optimiser's kParallelPatchWork raised together: lshape_r02_nolayer
  // p = 4 16.7 -> 14.3 ms, naca4412_a8_nolayer_fine p = 5 54.5 -> 29.3, star1_bl_1e-3 p = 5
  // 122 -> 96, naca0012_bl_1e-4 p = 5 143 -> 134, plate_holes_nolayer_coarse p = 5 and
  // naca0012_voronoi p = 4 the same.
  constexpr double kParallelWork = 150000;
  double work = 0;
  for (int e = 0; e < en.size(); ++e) work += std::pow(double(en.start[e + 1] - en.start[e]), 2);
  threads_ = work >= kParallelWork
                 ? std::max(1, options.threads > 0 ? options.threads : omp_get_num_procs())
                 : 1;
  colours_ = colour_elements(en, inc);
  dof_patterns(node_neighbours(en, inc), fixed_, condensed_, pattern_, coupling_pattern_);
}

Eigen::MatrixXi::ConstColXpr ElasticityAssembler::element_nodes(int e) const {
  return e < num_triangles_ ? kinds_[0].nodes.col(e) : kinds_[1].nodes.col(e - num_triangles_);
}

void ElasticityAssembler::split(int e, std::vector<int>& condensed, std::vector<int>& kept) const {
  const auto nodes = element_nodes(e);
  const int n = int(nodes.size());
  condensed.clear();
  kept.clear();
  for (int comp = 0; comp < 2; ++comp)
    for (int i = 0; i < n; ++i) (condensed_[nodes(i)] ? condensed : kept).push_back(comp * n + i);
}

void ElasticityAssembler::assemble(const Eigen::Matrix2Xd& x, const ElasticityCoefficients& c,
                                   EliminatedSystem& sys) const {
  const int num_dofs = this->num_dofs();
  if (x.cols() * 2 != num_dofs)
    throw Error("assemble_elasticity: " + std::to_string(x.cols()) + " positions for " +
                std::to_string(num_dofs / 2) + " nodes");
  pattern_.assign_zero(sys.K);
  coupling_pattern_.assign_zero(sys.coupling);
  sys.load = Eigen::VectorXd::Zero(num_dofs);
  sys.recovery.resize(recovery_start_.back());
  const int *outer = sys.K.outerIndexPtr(), *inner = sys.K.innerIndexPtr();
  const int *c_outer = sys.coupling.outerIndexPtr(), *c_inner = sys.coupling.innerIndexPtr();
  double* value = sys.K.valuePtr();
  double* c_value = sys.coupling.valuePtr();
  std::string failure;
  int failed_element = -1;

  // One team for all colours; the implicit barrier of each loop separates them.
#pragma omp parallel num_threads(threads_) if (threads_ > 1)
  {
    // One workspace per kind of element, sized once.
    Workspace works[2];
    for (int k = 0; k < 2; ++k) {
      const int n = int(kinds_[k].nodes.rows());
      works[k].X.resize(2, n);
      works[k].dof.resize(2 * n);
      works[k].order.resize(2 * n);
    }
    for (const std::vector<int>& colour : colours_) {
#pragma omp for schedule(static)
      for (std::size_t k = 0; k < colour.size(); ++k) {
        const int e = colour[k];  // 2D element index: triangles, then quadrilaterals
        const int kind = e < num_triangles_ ? 0 : 1;
        const int local = e - (kind == 0 ? 0 : num_triangles_);
        const Eigen::MatrixXi& nodes = kinds_[kind].nodes;
        const ElementTabulation& tab = kinds_[kind].tab;
        Workspace& w = works[kind];
        const int n = int(nodes.rows());
        const bool condensing = recovery_start_[e + 1] > recovery_start_[e];
        try {
          for (int i = 0; i < n; ++i) {
            w.X.col(i) = x.col(nodes(i, local));
            // Element dof (c, i) at c n + i (Eq 4.14) is global dof 2 node + c.
            w.dof[i] = 2 * nodes(i, local);
            w.dof[n + i] = 2 * nodes(i, local) + 1;
          }
          element_geometry(w.X, tab, w.geometry);
          evaluate(c, e, w);
          element_stiffness_lower(w.geometry, w.lambda, w.mu, w.Ke, w.scratch);
          element_load(w.geometry, tab.N, w.f, w.sigma_t, w.fe);
          if (condensing) condense(e, w, sys.recovery.data() + recovery_start_[e]);
        } catch (const std::exception& error) {
#pragma omp critical(homesh_assembly_failure)
          if (failed_element < 0 || e < failed_element) {
            failed_element = e;
            failure = error.what();
          }
          continue;
        }
        // The matrix, load and global dofs scattered: Ke, fe and dof, or those of the
        // element with its condensed dofs eliminated (exact in their lower triangle).
        const Eigen::MatrixXd* K = condensing ? &w.S : &w.Ke;
        const Eigen::VectorXd* f = condensing ? &w.fr : &w.fe;
        const std::vector<int>* dofs = condensing ? &w.rdof : &w.dof;
        const int m = int(dofs->size());
        auto ke = [&](int a, int b) { return a >= b ? (*K)(a, b) : (*K)(b, a); };
        std::iota(w.order.begin(), w.order.begin() + m, 0);
        std::sort(w.order.begin(), w.order.begin() + m,
                  [&](int a, int b) { return (*dofs)[a] < (*dofs)[b]; });
        // Each column's rows ascending, merged with the element's sorted dofs.
        for (int s = 0; s < m; ++s) {
          const int b = w.order[s], col = (*dofs)[b];
          if (fixed_[col]) {
            value[outer[col]] += (*K)(b, b);  // the diagonal heads its column
            int p = c_outer[col];
            for (int t = 0; t < m; ++t) {
              const int a = w.order[t], row = (*dofs)[a];
              if (fixed_[row]) continue;
              while (c_inner[p] != row) ++p;
              c_value[p] += ke(a, b);
            }
            continue;
          }
          sys.load(col) += (*f)(b);
          int p = outer[col];
          for (int t = s; t < m; ++t) {
            const int a = w.order[t], row = (*dofs)[a];
            if (fixed_[row]) continue;
            while (inner[p] != row) ++p;
            value[p] += ke(a, b);
          }
        }
      }
    }
  }
  if (failed_element >= 0)
    throw Error("assemble_elasticity: " +
                (failed_element < num_triangles_
                     ? "triangle " + std::to_string(failed_element)
                     : "quadrilateral " + std::to_string(failed_element - num_triangles_) +
                           " (2D element " + std::to_string(failed_element) + ")") +
                ": " + failure);
  for (int j = 0; j < num_dofs; ++j) {
    double& diagonal = value[outer[j]];
    if (!used_[j / 2] || condensed_[j / 2] || (fixed_[j] && diagonal == 0.0)) diagonal = 1.0;
  }
}

Eigen::VectorXd ElasticityAssembler::rhs(const EliminatedSystem& sys,
                                         const Eigen::VectorXd& g) const {
  if (g.size() != num_dofs())
    throw Error("assemble_elasticity: " + std::to_string(g.size()) + " prescribed values for " +
                std::to_string(num_dofs()) + " dofs");
  Eigen::VectorXd b = sys.load;
  b.noalias() -= sys.coupling * g;
  const int* outer = sys.K.outerIndexPtr();
  for (int j = 0; j < num_dofs(); ++j)
    if (fixed_[j]) b(j) = sys.K.valuePtr()[outer[j]] * g(j);
  return b;
}

void ElasticityAssembler::recover(const EliminatedSystem& sys, Eigen::VectorXd& u) const {
  if (u.size() != num_dofs())
    throw Error("assemble_elasticity: " + std::to_string(u.size()) + " displacements for " +
                std::to_string(num_dofs()) + " dofs");
  if (num_condensed_ == 0) return;
  if (sys.recovery.size() != recovery_start_.back())
    throw Error("assemble_elasticity: recover before assemble");
  const int num_2d = int(recovery_start_.size()) - 1;
#pragma omp parallel num_threads(threads_) if (threads_ > 1)
  {
    std::vector<int> c, r;
    Eigen::VectorXd ur;
#pragma omp for schedule(static)
    for (int e = 0; e < num_2d; ++e) {
      if (recovery_start_[e + 1] == recovery_start_[e]) continue;
      split(e, c, r);
      const auto nodes = element_nodes(e);
      const int n = int(nodes.size());
      // Element dof (c, i) at c n + i (Eq 4.14) is global dof 2 node + c.
      auto global = [&](int a) { return 2 * nodes(a % n) + a / n; };
      ur.resize(Eigen::Index(r.size()));
      for (std::size_t k = 0; k < r.size(); ++k) ur(Eigen::Index(k)) = u(global(r[k]));
      const double* data = sys.recovery.data() + recovery_start_[e];
      const Eigen::Index nc = Eigen::Index(c.size()), nr = Eigen::Index(r.size());
      const Eigen::Map<const Eigen::MatrixXd> Z(data, nc, nr);
      const Eigen::Map<const Eigen::VectorXd> z(data + nc * nr, nc);
      const Eigen::VectorXd uc = z - Z * ur;
      for (Eigen::Index k = 0; k < nc; ++k) u(global(c[std::size_t(k)])) = uc(k);
    }
  }
}

void ElasticityAssembler::condense(int e, Workspace& w, double* recovery) const {
  split(e, w.c, w.r);
  const Eigen::Index nc = Eigen::Index(w.c.size()), nr = Eigen::Index(w.r.size());
  // Ke is exact in its lower triangle: entry (a, b) is read from there.
  auto ke = [&](int a, int b) { return a >= b ? w.Ke(a, b) : w.Ke(b, a); };
  w.Kcc.resize(nc, nc);
  w.Kcr.resize(nc, nr);
  w.S.resize(nr, nr);
  w.fc.resize(nc);
  w.fr.resize(nr);
  for (Eigen::Index a = 0; a < nc; ++a) {
    for (Eigen::Index b = 0; b < nc; ++b) w.Kcc(a, b) = ke(w.c[a], w.c[b]);
    for (Eigen::Index b = 0; b < nr; ++b) w.Kcr(a, b) = ke(w.c[a], w.r[b]);
    w.fc(a) = w.fe(w.c[a]);
  }
  for (Eigen::Index b = 0; b < nr; ++b) {
    for (Eigen::Index a = b; a < nr; ++a) w.S(a, b) = ke(w.r[a], w.r[b]);
    w.fr(b) = w.fe(w.r[b]);
  }
  w.llt.compute(w.Kcc);
  if (w.llt.info() != Eigen::Success)
    throw Error("the stiffness of its interior nodes is not positive definite");
  Eigen::Map<Eigen::MatrixXd> Z(recovery, nc, nr);
  Eigen::Map<Eigen::VectorXd> z(recovery + nc * nr, nc);
  Z = w.llt.solve(w.Kcr);
  z = w.llt.solve(w.fc);
  w.S.triangularView<Eigen::Lower>() -= w.Kcr.transpose() * Z;
  w.fr.noalias() -= w.Kcr.transpose() * z;
  w.rdof.resize(std::size_t(nr));
  for (Eigen::Index k = 0; k < nr; ++k) w.rdof[std::size_t(k)] = w.dof[std::size_t(w.r[k])];
}

}  // namespace homesh
