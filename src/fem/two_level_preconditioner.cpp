#include "fem/two_level_preconditioner.h"

#include <memory>
#include <string>

#include "core/error.h"
#include "fem/cholmod_solver.h"

namespace homesh {

Preconditioner two_level_preconditioner(Preconditioner smoother, Eigen::SparseMatrix<double> P,
                                        const Eigen::SparseMatrix<double>& coarse) {
  if (coarse.rows() != coarse.cols() || P.cols() != coarse.rows())
    throw Error("two_level_preconditioner: the prolongation has " + std::to_string(P.cols()) +
                " columns for a coarse system of " + std::to_string(coarse.rows()) + " unknowns");
  if (coarse.rows() == 0) return smoother;  // no coarse space: one level
  auto factor = std::make_shared<CholmodFactor>();
  factor->analyze(coarse);
  factor->factorize(coarse);
  auto Pt = std::make_shared<const Eigen::SparseMatrix<double>>(P.transpose());
  auto Pm = std::make_shared<const Eigen::SparseMatrix<double>>(std::move(P));
  return [smoother = std::move(smoother), factor, Pm, Pt](const Eigen::VectorXd& r,
                                                          Eigen::VectorXd& z) {
    smoother(r, z);
    z += *Pm * factor->solve(*Pt * r);
  };
}

}  // namespace homesh
