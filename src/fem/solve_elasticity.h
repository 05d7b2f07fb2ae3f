#pragma once
// The elastic analogy end to end: assemble (Eqs 4.10-4.15), prescribe the
// boundary displacements (Eq 4.7), solve K x = p + b (Eq 4.13).
#include <Eigen/Core>

#include "core/mesh.h"
#include "fem/assemble_elasticity.h"
#include "fem/dirichlet.h"
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
