#include "element/gauss_jacobi.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>

#include "core/error.h"

namespace homesh {

LineQuadratureRule gauss_jacobi(int n, double alpha, double beta) {
  if (n < 1) throw Error("gauss_jacobi: " + std::to_string(n) + " points, need >= 1");
  if (alpha <= -1.0 || beta <= -1.0)
    throw Error("gauss_jacobi: exponents alpha = " + std::to_string(alpha) +
                ", beta = " + std::to_string(beta) + " must be > -1");
  const double s = alpha + beta;
  Eigen::VectorXd diagonal(n);
  Eigen::VectorXd off_diagonal(n - 1);
  // a_0 written without the factor (2k + s) that vanishes for s = 0.
  diagonal(0) = (beta - alpha) / (s + 2.0);
  for (int k = 1; k < n; ++k) {
    const double m = 2.0 * k + s;
    diagonal(k) = (beta * beta - alpha * alpha) / (m * (m + 2.0));
    off_diagonal(k - 1) =
        std::sqrt(4.0 * k * (k + alpha) * (k + beta) * (k + s) / (m * m * (m + 1.0) * (m - 1.0)));
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen;
  eigen.computeFromTridiagonal(diagonal, off_diagonal, Eigen::ComputeEigenvectors);
  if (eigen.info() != Eigen::Success)
    throw Error("gauss_jacobi: eigenvalue solver failed for n = " + std::to_string(n));

  const double beta_function =
      std::exp(std::lgamma(alpha + 1.0) + std::lgamma(beta + 1.0) - std::lgamma(s + 2.0));
  LineQuadratureRule rule;
  rule.points = (eigen.eigenvalues().array() + 1.0) / 2.0;
  rule.weights = beta_function * eigen.eigenvectors().row(0).transpose().array().square();
  return rule;
}

}  // namespace homesh
