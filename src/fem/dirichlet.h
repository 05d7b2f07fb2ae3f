#pragma once
// Prescribed displacements (thesis Eq 4.7, u = u_bar on the boundary; Eq 4.16
// for the boundary-layer push) on any set of nodes or single components, applied
// to an assembled system by symmetric elimination.
#include <Eigen/Core>
#include <vector>

#include "fem/assemble_elasticity.h"

namespace homesh {

/// Prescribed dofs (2 node + component, as LinearSystem) and their values. A dof
/// listed more than once takes its last value.
struct DirichletBC {
  std::vector<int> dofs;
  std::vector<double> values;

  /// Both components of `node`: u(node) = u.
  void fix(int node, const Eigen::Vector2d& u);
  /// One component (0: x, 1: y) of `node`.
  void fix(int node, int component, double value);
};

/// Applies bc to sys in place, keeping K symmetric: with g the prescribed
/// values (zero on free dofs), b_free -= K_free,fixed g; then the rows and
/// columns of the fixed dofs are zeroed except their diagonal K_jj (kept, so
/// that the diagonal scale and CG conditioning are unchanged; 1 if it was 0)
/// and b_j = K_jj g_j. The solution takes the value g_j at fixed dofs and
/// solves the reduced system elsewhere. Explicit zeros are pruned from K.
/// Throws homesh::Error if a dof is out of range or dofs and values differ in size.
void apply_dirichlet(const DirichletBC& bc, LinearSystem& sys);

}  // namespace homesh
