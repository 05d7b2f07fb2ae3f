#pragma once
// Repeated assembly of the elastic analogy (thesis Eqs 4.10-4.15) on one mesh
// connectivity with one set of prescribed dofs, as a deformation in load
// increments needs it: the sparsity pattern, the element colouring and the
// basis tabulation are built once; each assembly refills the values of the
// fixed pattern in parallel (OpenMP, one colour at a time, so that no two
// threads add into the same entry) without allocating per element. The dofs of
// nodes in one element only are condensed out element by element
// (AssemblyOptions::condense) and recovered after the solve (recover).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "core/mesh.h"
#include "fem/assemble_elasticity.h"
#include "fem/elasticity_coefficients.h"
#include "fem/element_tabulation.h"
#include "fem/sparse_pattern.h"

namespace homesh {

/// The assembled system with the prescribed dofs eliminated as apply_dirichlet
/// (fem/dirichlet.h) does it, the parts kept apart so that new prescribed
/// values need only a new right-hand side (ElasticityAssembler::rhs).
struct EliminatedSystem {
  /// Lower triangle: the free-free entries of sum_e Ke, and every diagonal
  /// (fixed dof j: sum_e (Ke)_jj, 1 if no element holds it; free dofs of nodes
  /// in no triangle nor quadrilateral: 1). Always the assembler's pattern.
  Eigen::SparseMatrix<double> K;
  /// The free-fixed block of sum_e Ke: rows free dofs, columns fixed dofs.
  Eigen::SparseMatrix<double> coupling;
  /// sum_e fe at free dofs, 0 at fixed ones.
  Eigen::VectorXd load;
  /// Static condensation (AssemblyOptions::condense): a condensed dof has the row
  /// u = 0 in K (unit diagonal, no load); K, coupling and load are those of the
  /// element matrices and loads with the element's condensed dofs c eliminated,
  /// S = K_rr - K_cr^T K_cc^-1 K_cr and f_r - K_cr^T K_cc^-1 f_c (r: its other dofs).
  /// Per element with condensed dofs, Z = K_cc^-1 K_cr (column-major) then
  /// z = K_cc^-1 f_c, for ElasticityAssembler::recover: u_c = z - Z u_r.
  Eigen::VectorXd recovery;
};

class ElasticityAssembler {
 public:
  struct Workspace;  ///< per-thread buffers of the element loop

  /// The connectivity of m (order, tri, quad, #nodes; its coordinates are not
  /// used) and the prescribed dofs (2 node + component, as LinearSystem;
  /// repeats allowed). Triangles and quadrilaterals are summed into one system,
  /// each at its own rule (tabulate_element, tabulate_quad_element); they are
  /// the 2D elements e = 0..T-1 and T..T+Q-1 (core/mesh.h) of QuadraturePoint.
  /// Throws homesh::Error if tri or quad does not fit the order, or a node or
  /// a dof is out of range.
  ElasticityAssembler(const Mesh& m, const std::vector<int>& fixed_dofs,
                      const AssemblyOptions& options = {});

  /// Refills sys for positions x (2 by #nodes) and coefficients c evaluated at
  /// the quadrature points as in assemble_elasticity. Throws homesh::Error
  /// naming the triangle or quadrilateral (the lowest 2D element index) if an
  /// element is invalid or a coefficient out of range.
  void assemble(const Eigen::Matrix2Xd& x, const ElasticityCoefficients& c,
                EliminatedSystem& sys) const;

  /// The right-hand side for prescribed values g (2 #nodes, read at fixed dofs):
  /// load - coupling g at free dofs, K_jj g_j at fixed dofs (so x_j = g_j), 0 at
  /// condensed dofs.
  Eigen::VectorXd rhs(const EliminatedSystem& sys, const Eigen::VectorXd& g) const;

  /// The condensed dofs of u (the solution of sys.K u = rhs(sys, g)) recovered
  /// from the others: u_c = z - Z u_r per element (see EliminatedSystem::recovery).
  void recover(const EliminatedSystem& sys, Eigen::VectorXd& u) const;

  int num_dofs() const { return static_cast<int>(fixed_.size()); }
  /// Dofs condensed out of the global system (0 without AssemblyOptions::condense).
  int num_condensed_dofs() const { return num_condensed_; }
  const std::vector<char>& fixed() const { return fixed_; }
  /// Colour classes of 2D element indices: elements of one class share no node.
  const std::vector<std::vector<int>>& colours() const { return colours_; }

 private:
  // One kind of 2D element: its connectivity (nodes by elements) and the
  // tabulation of its basis at its rule.
  struct Kind {
    Eigen::MatrixXi nodes;
    ElementTabulation tab;
  };
  Kind kinds_[2];  // triangles, quadrilaterals (2D elements num_triangles_..)
  int num_triangles_ = 0;
  std::vector<char> fixed_;      // per dof
  std::vector<char> used_;       // per node: in some triangle or quadrilateral
  std::vector<char> condensed_;  // per node: its dofs condensed (in one element, both free)
  int num_condensed_ = 0;
  int threads_ = 1;  // of the element loops (AssemblyOptions::threads, where worth it)
  // Per 2D element, the start of its Z and z in EliminatedSystem::recovery (#2D + 1).
  std::vector<Eigen::Index> recovery_start_;
  std::vector<std::vector<int>> colours_;
  // 2D element e's nodes (a triangle's, or quadrilateral e - #triangles').
  Eigen::MatrixXi::ConstColXpr element_nodes(int e) const;
  // The element's local dofs (c n + i: component c of its node i) condensed and kept.
  void split(int e, std::vector<int>& condensed, std::vector<int>& kept) const;
  // Element e's Ke and fe in w with its condensed dofs eliminated: w.S (lower), w.fr and
  // w.rdof; its Z and z written at `recovery` (EliminatedSystem::recovery).
  void condense(int e, Workspace& w, double* recovery) const;
  // Lower free-free plus diagonal; free-fixed.
  SparsePattern pattern_, coupling_pattern_;
};

}  // namespace homesh
