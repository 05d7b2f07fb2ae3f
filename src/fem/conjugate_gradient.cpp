#include "fem/conjugate_gradient.h"

#include "fem/symmetric_product.h"

namespace homesh {

ConjugateGradientResult conjugate_gradient(const Eigen::SparseMatrix<double>& K,
                                           const Eigen::VectorXd& b, const Eigen::VectorXd& x0,
                                           const Preconditioner& M, double tolerance,
                                           int max_iterations) {
  ConjugateGradientResult result;
  result.x = x0.size() == b.size() ? x0 : Eigen::VectorXd::Zero(b.size());
  const double b_norm = b.norm();
  if (b_norm == 0.0) {
    result.x.setZero();
    result.converged = true;
    return result;
  }
  if (!K.isCompressed())
    return conjugate_gradient(Eigen::SparseMatrix<double>(K), b, x0, M, tolerance, max_iterations);
  const SymmetricProduct K_times(K);
  Eigen::VectorXd Kx;
  K_times.apply(result.x, Kx);
  Eigen::VectorXd r = b - Kx;
  Eigen::VectorXd z, p, Kp(b.size());
  M(r, z);
  p = z;
  double rz = r.dot(z);
  double r_norm = r.norm();
  while (r_norm > tolerance * b_norm && result.iterations < max_iterations) {
    K_times.apply(p, Kp);
    const double alpha = rz / p.dot(Kp);
    result.x += alpha * p;
    r -= alpha * Kp;
    M(r, z);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
    r_norm = r.norm();
    ++result.iterations;
  }
  result.relative_residual = r_norm / b_norm;
  result.converged = r_norm <= tolerance * b_norm;
  return result;
}

}  // namespace homesh
