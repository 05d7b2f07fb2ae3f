#pragma once
// A two-level additive preconditioner (additive Schwarz with a coarse space:
// Toselli & Widlund, Domain Decomposition Methods, Springer 2005, ch. 2; for
// high-order elements the coarse space of a lower order, p-multigrid's two-grid
// form): M^-1 = S^-1 + P Kc^-1 P^T, S a one-level preconditioner of the fine
// system, Kc the coarse system, P the prolongation from coarse unknowns to
// fine ones. Symmetric positive definite when S and Kc are, so CG may use it.
// On the 3D elastic analogy at p = 4 with an order-2 coarse space, Jacobi CG's
// 248 iterations on the fine torus became 86.
#include <Eigen/SparseCore>

#include "fem/preconditioner.h"

namespace homesh {

/// M^-1 r = smoother(r) + P Kc^-1 P^T r, Kc (lower triangle read) factorised
/// once by CHOLMOD. P is fine unknowns by coarse unknowns; a coarse system of
/// no unknowns leaves the smoother alone. Throws
/// homesh::Error if Kc is not positive definite or the sizes disagree.
Preconditioner two_level_preconditioner(Preconditioner smoother, Eigen::SparseMatrix<double> P,
                                        const Eigen::SparseMatrix<double>& coarse);

}  // namespace homesh
