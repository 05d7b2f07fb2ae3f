#include "fem/preconditioner.h"

#include <Eigen/IterativeLinearSolvers>
#include <memory>
#include <utility>

#include "core/error.h"

namespace homesh {
namespace {

Preconditioner jacobi(const Eigen::SparseMatrix<double>& K) {
  const Eigen::VectorXd d = K.diagonal();
  if (!(d.size() == 0 || d.minCoeff() > 0.0))
    throw Error("make_preconditioner: jacobi needs a positive diagonal");
  const Eigen::VectorXd inverse = d.cwiseInverse();
  return [inverse](const Eigen::VectorXd& r, Eigen::VectorXd& z) { z = inverse.cwiseProduct(r); };
}

Preconditioner block_jacobi(const Eigen::SparseMatrix<double>& K) {
  const Eigen::Index nodes = K.rows() / 2;
  if (2 * nodes != K.rows()) throw Error("make_preconditioner: block_jacobi needs 2 dofs a node");
  // The inverse of each 2 by 2 block [a b; b c], stored as its (a', b', c').
  Eigen::Matrix3Xd inverse(3, nodes);
  for (Eigen::Index i = 0; i < nodes; ++i) {
    const double a = K.coeff(2 * i, 2 * i), b = K.coeff(2 * i + 1, 2 * i),
                 c = K.coeff(2 * i + 1, 2 * i + 1);
    const double det = a * c - b * b;
    if (!(a > 0.0 && det > 0.0))
      throw Error("make_preconditioner: block_jacobi block of node " + std::to_string(i) +
                  " is not positive definite");
    inverse.col(i) << c / det, -b / det, a / det;
  }
  return [inverse](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
    z.resize(r.size());
    for (Eigen::Index i = 0; i < inverse.cols(); ++i) {
      const double rx = r(2 * i), ry = r(2 * i + 1);
      z(2 * i) = inverse(0, i) * rx + inverse(1, i) * ry;
      z(2 * i + 1) = inverse(1, i) * rx + inverse(2, i) * ry;
    }
  };
}

Preconditioner incomplete_cholesky(const Eigen::SparseMatrix<double>& K) {
  using Factor = Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>;
  auto factor = std::make_shared<Factor>(K);
  if (factor->info() != Eigen::Success)
    throw Error("make_preconditioner: ichol factorisation failed");
  return [factor](const Eigen::VectorXd& r, Eigen::VectorXd& z) { z = factor->solve(r); };
}

using PreconditionerFactory = Preconditioner (*)(const Eigen::SparseMatrix<double>&);

// The one list of preconditioners: name and factory.
const std::vector<std::pair<std::string, PreconditionerFactory>>& preconditioner_registry() {
  static const std::vector<std::pair<std::string, PreconditionerFactory>> entries = {
      {"jacobi", jacobi}, {"block_jacobi", block_jacobi}, {"ichol", incomplete_cholesky}};
  return entries;
}

}  // namespace

const std::vector<std::string>& preconditioner_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const auto& entry : preconditioner_registry()) list.push_back(entry.first);
    return list;
  }();
  return names;
}

Preconditioner make_preconditioner(const std::string& name, const Eigen::SparseMatrix<double>& K) {
  for (const auto& [known, factory] : preconditioner_registry())
    if (known == name) return factory(K);
  std::string list;
  for (const std::string& n : preconditioner_names()) list += (list.empty() ? "" : ", ") + n;
  throw Error("make_preconditioner: unknown preconditioner '" + name + "' (known: " + list + ")");
}

}  // namespace homesh
