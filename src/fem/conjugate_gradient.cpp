#include "fem/conjugate_gradient.h"

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
  // K is symmetric: its compressed column storage read as rows is K again, and
  // Eigen shares a row-major sparse times dense product among its OpenMP
  // threads (the column-major one runs on one).
  const Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>> R(
      K.rows(), K.cols(), K.nonZeros(), K.outerIndexPtr(), K.innerIndexPtr(), K.valuePtr());
  Eigen::VectorXd r = b - R * result.x;
  Eigen::VectorXd z, p, Kp(b.size());
  M(r, z);
  p = z;
  double rz = r.dot(z);
  double r_norm = r.norm();
  while (r_norm > tolerance * b_norm && result.iterations < max_iterations) {
    Kp.noalias() = R * p;
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
