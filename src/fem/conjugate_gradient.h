#pragma once
// The preconditioned conjugate gradient method (Hestenes & Stiefel 1952), the
// iterative solver of the thesis (Sec 4.2.2, which reports N, the number of
// iterations per deformation step).
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "fem/preconditioner.h"

namespace homesh {

struct ConjugateGradientResult {
  Eigen::VectorXd x;
  int iterations = 0;
  double relative_residual = 0.0;  // ||b - K x|| / ||b|| (0 if b = 0)
  bool converged = false;
};

/// Solves K x = b, K symmetric positive definite given by its lower triangle
/// (compressed; fem/symmetric_product.h multiplies by it), from the
/// initial guess x0 (same size as b; zero if empty), until the recursively
/// updated residual satisfies ||r|| <= tolerance ||b|| or after max_iterations.
/// Each iteration: one product with K, one preconditioner application M^-1 r.
ConjugateGradientResult conjugate_gradient(const Eigen::SparseMatrix<double>& K,
                                           const Eigen::VectorXd& b, const Eigen::VectorXd& x0,
                                           const Preconditioner& M, double tolerance,
                                           int max_iterations);

}  // namespace homesh
