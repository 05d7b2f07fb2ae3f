#pragma once
// The linear solve through PETSc (issue 24): the elastic analogy's systems
// solved on PETSC_COMM_WORLD, so that `mpirun -n N homesh ...` shares the
// solve among N processes. Every process runs the whole pipeline on the whole
// mesh (the mesh is replicated) and rank 0 alone writes; the 3D analogy's
// system is assembled by each process for its own rows only
// (petsc_solve_rows), so its memory, the largest part at p = 3-4, is shared;
// the solution is gathered to every rank, so all go on with the same mesh. Conjugate gradients with
// the Jacobi preconditioner by default, whose iterates do not depend on how the rows are split
// (only the rounding of the sums does), so N processes give the mesh one gives; PETSc's options
// database (PETSC_OPTIONS, e.g. "-pc_type gamg") chooses others.
//
// Built only where PETSc was found (Debian's libpetsc-real-dev and MPI);
// otherwise the "petsc" method says so.
#include <Eigen/SparseCore>

#include "fem/linear_solver.h"

namespace homesh {

/// Whether this build of homesh has PETSc.
bool petsc_available();

/// Whether an MPI launcher (mpirun, mpiexec, srun) started this process.
bool mpi_launched();

/// For a program's main: under an MPI launcher, initialises PETSc (and MPI)
/// for the whole run and finalises it on destruction; otherwise does nothing
/// (a "petsc" solve then initialises PETSc on first use, in one process).
/// root(): whether this process writes (rank 0, or not launched by MPI).
class ParallelSession {
 public:
  ParallelSession();
  ~ParallelSession();
  ParallelSession(const ParallelSession&) = delete;
  ParallelSession& operator=(const ParallelSession&) = delete;
  bool root() const { return rank_ == 0; }

 private:
  bool initialised_ = false;
  int rank_ = 0;
};

/// This process's rows of a distributed system of n unknowns, split as PETSc's
/// PETSC_DECIDE does (n / size each, the first n % size one more): all of them
/// in one process or in a build without PETSc.
struct RowShare {
  int first = 0, count = 0;
};
RowShare petsc_rows(int n);

/// As petsc_solve, every process passing only its rows (petsc_rows(n)): `rows`
/// count by n, both triangles, and b and guess (or empty) of those rows. The
/// solution is still gathered to every process. The system's memory is then
/// shared: no process holds the whole matrix.
LinearSolveResult petsc_solve_rows(int n, const Eigen::SparseMatrix<double, Eigen::RowMajor>& rows,
                                   const Eigen::VectorXd& b, const Eigen::VectorXd& guess,
                                   const LinearSolverOptions& o);

/// Solves K x = b, K symmetric positive definite (`full`: both triangles, as
/// rows), with PETSc's KSP (CG with PCJACOBI; PCNONE if o.preconditioner is
/// "none"; PETSC_OPTIONS overrides both) to ||b - K x|| <= o.tolerance ||b||,
/// from `guess` if not empty. Every process passes the same K and b and gets
/// the whole x. Throws homesh::Error if the solve does not converge or homesh
/// was built without PETSc.
LinearSolveResult petsc_solve(const Eigen::SparseMatrix<double, Eigen::RowMajor>& full,
                              const Eigen::VectorXd& b, const Eigen::VectorXd& guess,
                              const LinearSolverOptions& o);

}  // namespace homesh
