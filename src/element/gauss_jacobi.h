#pragma once
// Gauss-Jacobi quadrature on [0, 1] for the weight (1 - t)^alpha t^beta.
#include <Eigen/Core>

namespace homesh {

/// Points and weights of a rule on [0, 1]; the weights sum to the integral of
/// the rule's weight function.
struct LineQuadratureRule {
  Eigen::VectorXd points;
  Eigen::VectorXd weights;
};

/// The n-point Gauss rule (n >= 1) for int_0^1 f(t) (1 - t)^alpha t^beta dt,
/// alpha, beta > -1: exact for polynomials f of degree <= 2n - 1, points
/// increasing in (0, 1), weights positive and summing to B(alpha+1, beta+1).
///
/// Golub & Welsch (1969): the points are the eigenvalues of the symmetric
/// tridiagonal Jacobi matrix of the monic Jacobi polynomials P_k^(alpha,beta)
/// on [-1, 1] (diagonal a_k, off-diagonal sqrt(b_k)),
///   a_k = (beta^2 - alpha^2) / ((2k+s)(2k+s+2)),  s = alpha + beta,
///   b_k = 4k(k+alpha)(k+beta)(k+s) / ((2k+s)^2 (2k+s+1)(2k+s-1)),
/// mapped by t = (x + 1) / 2; the weights are B(alpha+1, beta+1) times the
/// squared first components of the unit eigenvectors.
LineQuadratureRule gauss_jacobi(int n, double alpha, double beta);

}  // namespace homesh
