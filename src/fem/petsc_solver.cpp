#include "fem/petsc_solver.h"

#include <cstdlib>
#include <string>

#include "core/error.h"

#ifdef HOMESH_HAVE_PETSC
#include <petscksp.h>
#endif

namespace homesh {

bool mpi_launched() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(v)) return true;
  return false;
}

#ifdef HOMESH_HAVE_PETSC

namespace {

void check(PetscErrorCode code, const char* what) {
  if (code != 0)
    throw Error(std::string("solve_linear_system: petsc: ") + what + " failed (PETSc error " +
                std::to_string(static_cast<int>(code)) + ")");
}

// PETSc's own handlers would replace homesh's (which remove a pending output
// on SIGINT/SIGTERM) and trap signals homesh leaves alone.
void quiet_signals() { PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr); }

// Initialises PETSc (and MPI) unless something did already (a ParallelSession,
// petsc4py in the same Python process); true if this call did.
bool start_petsc() {
  PetscBool up = PETSC_FALSE;
  check(PetscInitialized(&up), "PetscInitialized");
  if (up) return false;
  quiet_signals();
  // PETSc reads its options from PETSC_OPTIONS (the command line is homesh's).
  check(PetscInitializeNoArguments(), "PetscInitialize");
  return true;
}

// PETSc started on first use when no ParallelSession did: one process,
// finalised at exit.
void ensure_petsc() {
  if (start_petsc())
    std::atexit([] {
      PetscBool finalised = PETSC_FALSE;
      PetscFinalized(&finalised);
      if (!finalised) PetscFinalize();
    });
}

// RAII for PETSc objects.
template <class T, PetscErrorCode (*Destroy)(T*)>
struct Owned {
  T p = nullptr;
  ~Owned() {
    if (p) Destroy(&p);
  }
};

}  // namespace

bool petsc_available() { return true; }

ParallelSession::ParallelSession() {
  if (!mpi_launched()) return;
  initialised_ = start_petsc();
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
}

ParallelSession::~ParallelSession() {
  if (initialised_) PetscFinalize();
}

RowShare petsc_rows(int n) {
  if (!mpi_launched()) return {0, n};
  ensure_petsc();
  int rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  return {rank * (n / size) + std::min(rank, n % size), n / size + (rank < n % size ? 1 : 0)};
}

LinearSolveResult petsc_solve(const Eigen::SparseMatrix<double, Eigen::RowMajor>& full,
                              const Eigen::VectorXd& b, const Eigen::VectorXd& guess,
                              const LinearSolverOptions& o) {
  ensure_petsc();
  const int n = static_cast<int>(full.rows());
  const RowShare share = petsc_rows(n);
  return petsc_solve_rows(
      n, full.middleRows(share.first, share.count), b.segment(share.first, share.count),
      guess.size() ? Eigen::VectorXd(guess.segment(share.first, share.count)) : Eigen::VectorXd(),
      o);
}

LinearSolveResult petsc_solve_rows(int n_rows,
                                   const Eigen::SparseMatrix<double, Eigen::RowMajor>& mine,
                                   const Eigen::VectorXd& b, const Eigen::VectorXd& guess,
                                   const LinearSolverOptions& o) {
  ensure_petsc();
  const MPI_Comm comm = PETSC_COMM_WORLD;
  const PetscInt n = static_cast<PetscInt>(n_rows);
  const RowShare share = petsc_rows(n_rows);
  const PetscInt local = share.count;
  if (mine.rows() != local || mine.cols() != n || b.size() != local ||
      (guess.size() && guess.size() != local))
    throw Error("solve_linear_system: petsc got " + std::to_string(mine.rows()) +
                " rows for this process's " + std::to_string(local));
  // This process's rows of the matrix, in CSR.
  std::vector<PetscInt> row(static_cast<std::size_t>(local) + 1), col;
  std::vector<PetscScalar> value;
  row[0] = 0;
  for (PetscInt i = 0; i < local; ++i) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(mine, i); it; ++it) {
      col.push_back(static_cast<PetscInt>(it.col()));
      value.push_back(it.value());
    }
    row[static_cast<std::size_t>(i) + 1] = static_cast<PetscInt>(col.size());
  }
  Owned<Mat, MatDestroy> A;
  check(MatCreateMPIAIJWithArrays(comm, local, local, n, n, row.data(), col.data(), value.data(),
                                  &A.p),
        "MatCreateMPIAIJWithArrays");
  Owned<Vec, VecDestroy> rhs, x;
  check(MatCreateVecs(A.p, &x.p, &rhs.p), "MatCreateVecs");
  {
    PetscScalar* r = nullptr;
    PetscScalar* s = nullptr;
    check(VecGetArray(rhs.p, &r), "VecGetArray");
    check(VecGetArray(x.p, &s), "VecGetArray");
    for (PetscInt i = 0; i < local; ++i) {
      r[i] = b(i);
      s[i] = guess.size() ? guess(i) : 0.0;
    }
    VecRestoreArray(rhs.p, &r);
    VecRestoreArray(x.p, &s);
  }
  Owned<KSP, KSPDestroy> ksp;
  check(KSPCreate(comm, &ksp.p), "KSPCreate");
  check(KSPSetOperators(ksp.p, A.p, A.p), "KSPSetOperators");
  check(KSPSetType(ksp.p, KSPCG), "KSPSetType");
  PC pc = nullptr;
  check(KSPGetPC(ksp.p, &pc), "KSPGetPC");
  check(PCSetType(pc, o.preconditioner == "none" ? PCNONE : PCJACOBI), "PCSetType");
  check(KSPSetNormType(ksp.p, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  const PetscInt limit = o.max_iterations > 0 ? o.max_iterations : std::max<PetscInt>(n, 1);
  check(KSPSetTolerances(ksp.p, o.tolerance, 0.0, PETSC_DEFAULT, limit), "KSPSetTolerances");
  check(KSPSetInitialGuessNonzero(ksp.p, guess.size() ? PETSC_TRUE : PETSC_FALSE),
        "KSPSetInitialGuessNonzero");
  check(KSPSetFromOptions(ksp.p), "KSPSetFromOptions");
  check(KSPSolve(ksp.p, rhs.p, x.p), "KSPSolve");
  KSPConvergedReason reason;
  PetscInt iterations = 0;
  PetscReal residual = 0;
  check(KSPGetConvergedReason(ksp.p, &reason), "KSPGetConvergedReason");
  check(KSPGetIterationNumber(ksp.p, &iterations), "KSPGetIterationNumber");
  check(KSPGetResidualNorm(ksp.p, &residual), "KSPGetResidualNorm");
  if (reason < 0)
    throw Error("solve_linear_system: petsc cg did not converge in " +
                std::to_string(static_cast<long>(iterations)) + " iterations (" +
                KSPConvergedReasons[reason] + ")");

  // The whole solution on every process.
  Owned<VecScatter, VecScatterDestroy> scatter;
  Owned<Vec, VecDestroy> all;
  check(VecScatterCreateToAll(x.p, &scatter.p, &all.p), "VecScatterCreateToAll");
  check(VecScatterBegin(scatter.p, x.p, all.p, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(scatter.p, x.p, all.p, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  LinearSolveResult out;
  out.x.resize(n);
  const PetscScalar* a = nullptr;
  check(VecGetArrayRead(all.p, &a), "VecGetArrayRead");
  for (PetscInt i = 0; i < n; ++i) out.x(i) = a[i];
  VecRestoreArrayRead(all.p, &a);
  out.iterations = static_cast<int>(iterations);
  PetscReal b_norm = 0;
  check(VecNorm(rhs.p, NORM_2, &b_norm), "VecNorm");
  out.relative_residual = b_norm > 0 ? static_cast<double>(residual / b_norm) : 0.0;
  return out;
}

#else

bool petsc_available() { return false; }

ParallelSession::ParallelSession() {}
ParallelSession::~ParallelSession() = default;

RowShare petsc_rows(int n) { return {0, n}; }

LinearSolveResult petsc_solve_rows(int, const Eigen::SparseMatrix<double, Eigen::RowMajor>&,
                                   const Eigen::VectorXd&, const Eigen::VectorXd&,
                                   const LinearSolverOptions& o) {
  return petsc_solve({}, {}, {}, o);
}

LinearSolveResult petsc_solve(const Eigen::SparseMatrix<double, Eigen::RowMajor>&,
                              const Eigen::VectorXd&, const Eigen::VectorXd&,
                              const LinearSolverOptions&) {
  throw Error(
      "solve_linear_system: this homesh was built without PETSc (install libpetsc-real-dev "
      "and rebuild)");
}

#endif

}  // namespace homesh
