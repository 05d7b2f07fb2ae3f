#pragma once
// Preconditioners for the conjugate gradient method, chosen by name.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <string>
#include <vector>

namespace homesh {

/// z = M^-1 r for a symmetric positive definite approximation M of K.
using Preconditioner = std::function<void(const Eigen::VectorXd& r, Eigen::VectorXd& z)>;

/// The preconditioner names, in the order make_preconditioner accepts them.
const std::vector<std::string>& preconditioner_names();

/// A preconditioner for the symmetric positive definite K (full or lower
/// triangle storage: only the lower triangle is read):
///  - "jacobi": M = diag(K);
///  - "block_jacobi": M = the 2 by 2 diagonal blocks of the nodes (dofs 2i, 2i+1,
///    the interleaved numbering of LinearSystem); the thesis' element-by-element
///    PCG (Sec 4.2.2) does not name its preconditioner, these two are the
///    classical choices that need no more than K's diagonal;
///  - "ichol": incomplete Cholesky with zero fill beyond K's pattern after AMD
///    reordering (Eigen::IncompleteCholesky, Lin & More 1999 diagonal shifts).
/// Throws homesh::Error on an unknown name or a non-positive pivot.
Preconditioner make_preconditioner(const std::string& name, const Eigen::SparseMatrix<double>& K);

}  // namespace homesh
