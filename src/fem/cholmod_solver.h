#pragma once
// Adapter to CHOLMOD (SuiteSparse, Chen, Davis, Hager & Rajamanickam 2008), the
// supernodal sparse Cholesky factorisation, through Eigen's CholmodSupport. It is
// compiled in when HOMESH_WITH_CHOLMOD is defined and cholmod is linked; without
// it the library still builds and cholmod_solve reports that it is missing.
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace homesh {

/// Whether this build has CHOLMOD.
bool cholmod_available();

/// x solving K x = b, K symmetric positive definite (its lower triangle is
/// read), by CHOLMOD's LL^T with its default (AMD/METIS) ordering. Throws
/// homesh::Error if CHOLMOD is not built in or the factorisation fails.
Eigen::VectorXd cholmod_solve(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& b);

}  // namespace homesh
