#pragma once
// The elastic analogy end to end: assemble (Eqs 4.10-4.15), prescribe the
// boundary displacements (Eq 4.7), solve K x = p + b (Eq 4.13); once, or
// repeatedly on one mesh connectivity (ElasticitySolver).
#include <Eigen/Core>
#include <vector>

#include "core/mesh.h"
#include "fem/assemble_elasticity.h"
#include "fem/dirichlet.h"
#include "fem/elasticity_assembler.h"
#include "fem/elasticity_coefficients.h"
#include "fem/linear_solver.h"

namespace homesh {

struct ElasticityOptions {
  AssemblyOptions assembly;
  LinearSolverOptions solver;
};

struct ElasticitySolution {
  /// 2 by #nodes displacement of every node of the mesh.
  Eigen::Matrix2Xd u;
  int iterations = 0;              // CG iterations (0 for direct solvers)
  double relative_residual = 0.0;  // of the eliminated system
};

/// Repeated solves on one connectivity with one set of prescribed dofs, as the
/// load increments of a deformation need them: the pattern and element
/// colouring (ElasticityAssembler) and the solver's symbolic analysis
/// (LinearSolver) are computed once. solve() assembles and factorises on the
/// current node positions; resolve() reuses that factorisation for new
/// prescribed values (the stiffness and loads unchanged), at the cost of one
/// back substitution.
class ElasticitySolver {
 public:
  /// m's connectivity and the dofs of bc (their values are not used here).
  ElasticitySolver(const Mesh& m, const DirichletBC& bc, const ElasticityOptions& options = {});

  /// Displacements on positions x (2 by #nodes) with coefficients c and the
  /// prescribed values of bc, whose dofs must be those given at construction.
  /// `guess` (2 by #nodes, or empty for zero) is the initial iterate of CG.
  ElasticitySolution solve(const Eigen::Matrix2Xd& x, const ElasticityCoefficients& c,
                           const DirichletBC& bc,
                           const Eigen::Matrix2Xd& guess = Eigen::Matrix2Xd());

  /// The same with the positions and coefficients of the last solve() and new
  /// prescribed values. Throws homesh::Error if nothing was solved yet.
  ElasticitySolution resolve(const DirichletBC& bc,
                             const Eigen::Matrix2Xd& guess = Eigen::Matrix2Xd());

  /// Numeric factorisations and symbolic analyses done so far.
  int factorizations() const { return factorizations_; }
  int analyses() const { return solver_.analyses(); }

 private:
  Eigen::VectorXd prescribed(const DirichletBC& bc) const;
  ElasticitySolution finish(const Eigen::VectorXd& b, const Eigen::Matrix2Xd& guess) const;

  ElasticityAssembler assembler_;
  LinearSolver solver_;
  EliminatedSystem system_;
  int factorizations_ = 0;
};

/// The displacement of the nodes of m under the coefficients c with the dofs of
/// bc prescribed; every other boundary is traction free. `guess` (2 by #nodes,
/// or empty for zero) is the initial iterate of CG, e.g. the previous step's
/// solution.
/// Throws homesh::Error on invalid elements or coefficients, unknown solver
/// names, or solver failure (a singular system: too few dofs prescribed to
/// remove the rigid motions).
ElasticitySolution solve_elasticity(const Mesh& m, const ElasticityCoefficients& c,
                                    const DirichletBC& bc, const ElasticityOptions& options = {},
                                    const Eigen::Matrix2Xd& guess = Eigen::Matrix2Xd());

}  // namespace homesh
