#pragma once
// Sparse direct solve K x = b with MUMPS (multifrontal LU / LDLᵀ; Amestoy et al., "A fully
// asynchronous multifrontal solver using distributed dynamic scheduling", SIAM J. Matrix Anal.
// Appl. 23 (2001)), Debian's PT-SCOTCH build, through its C interface dmumps_c.h.
//
// Every rank hands MUMPS the rows it owns of the distributed Tpetra matrix (distributed
// assembled input, ICNTL(18) = 3). A solve goes through the phases of a sparse direct solver,
// each in its own file and each keeping what the next solve can reuse:
//   numbering   MUMPS's global indices of the rows (the row map's global ids when they are
//               0 .. n-1, else a contiguous renumbering), this rank's entries as keys, the
//               right-hand side gathered to rank 0 and the solution scattered back
//               (mumps_numbering.hpp); rebuilt when the row map changes;
//   pattern     the symbolic analysis (ordering), done once per sparsity pattern and reused
//               while the matrices' patterns stay inside it (mumps_pattern.hpp);
//   numeric     the factorisation, reused while the values do not change; with Schur updates
//               (symmetric matrices) a dense update of the Schur complement on the rows that
//               changed instead (mumps_schur.hpp, schur_update.hpp);
//   solve       the forward and backward substitution on rank 0.

#include <memory>
#include <string>

#include "assembly/tpetra_types.hpp"
#include "io/solver_settings.hpp"  // MumpsOptions, read from the `MUMPS` sublist

namespace grout {

/// Counters of what the solver did (for tests and benchmarks).
struct MumpsStatistics {
  int analyses = 0;              ///< symbolic analyses (job 1): once per sparsity pattern
  int factorisations = 0;        ///< numeric factorisations (job 2), retries included
  int solves = 0;                ///< forward/backward substitutions (job 3)
  int workspace_retries = 0;     ///< factorisations repeated with more workspace (INFOG(1) -8/-9)
  double flops = 0.0;            ///< floating-point operations of the last factorisation, RINFOG(3)
  long long factor_entries = 0;  ///< entries in the factors of the last one, INFOG(29)
  int schur_updates = 0;         ///< matrices solved by a dense Schur update (no factorisation)
  int schur_size = 0;            ///< rows in the Schur set of the last analysis (0: none)
};

class MumpsSolver {
 public:
  explicit MumpsSolver(MumpsOptions options = {});
  ~MumpsSolver();
  MumpsSolver(const MumpsSolver&) = delete;
  MumpsSolver& operator=(const MumpsSolver&) = delete;

  /// Solve K x = b (K square, range map = row map, x and b on K's row map). Collective.
  /// Throws std::runtime_error when MUMPS reports an error (e.g. a singular matrix), on every
  /// rank alike.
  void solve(const Teuchos::RCP<const Matrix>& K, const Vector& b, Vector& x);

  const MumpsStatistics& statistics() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// With more than one MPI rank and OpenBLAS as the BLAS: one OpenBLAS thread per rank, unless
/// the user set OPENBLAS_NUM_THREADS (or OMP_NUM_THREADS). Ranks and BLAS threads would
/// otherwise compete for the same cores.
void limit_blas_threads_under_mpi(int num_ranks);

/// For its lifetime: OpenBLAS on one thread, unless the user set OPENBLAS_NUM_THREADS (or
/// GOTO_NUM_THREADS, OMP_NUM_THREADS), whose count is then kept; the previous count is
/// restored at the end. OpenBLAS's rounding depends on its thread count (docs/performance.md,
/// "MUMPS as the default direct solver in 3D"), and a 1-rank run has 2 threads where a 2-rank
/// run has 1 (limit_blas_threads_under_mpi): a solve that must not depend on the rank count
/// runs under this guard. No effect with another BLAS.
class SingleBlasThread {
 public:
  SingleBlasThread();
  ~SingleBlasThread();
  SingleBlasThread(const SingleBlasThread&) = delete;
  SingleBlasThread& operator=(const SingleBlasThread&) = delete;

 private:
  int restore_ = 0;  // thread count to restore; 0: nothing was changed
};

}  // namespace grout
