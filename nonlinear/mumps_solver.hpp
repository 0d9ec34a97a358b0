#pragma once
// Sparse direct solve K x = b with MUMPS (multifrontal LU / LDLᵀ; Amestoy et al., "A fully
// asynchronous multifrontal solver using distributed dynamic scheduling", SIAM J. Matrix Anal.
// Appl. 23 (2001)), Debian's PT-SCOTCH build, through its C interface dmumps_c.h.
//
// Every rank hands MUMPS the rows it owns of the distributed Tpetra matrix (distributed
// assembled input, ICNTL(18) = 3, 1-based indices: the row map's global ids when they are
// 0 .. n-1, so that MUMPS sees the same matrix on any number of ranks, else a contiguous
// renumbering of the row map); the right-hand side is gathered on rank 0 and the solution scattered
// back with a Tpetra Export/Import. The symbolic analysis (ordering) is done once per sparsity
// pattern and reused while only the values change (Newton iterations with an unchanged active set);
// the numeric factorisation is reused while the values do not change either.

#include <Teuchos_ParameterList.hpp>
#include <memory>
#include <string>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// Options of the `Linear Solver/MUMPS` sublist.
struct MumpsOptions {
  /// Fill-reducing ordering: scotch (SCOTCH on the gathered graph, ICNTL(7) = 3), ptscotch
  /// (parallel PT-SCOTCH, ICNTL(28) = 2, ICNTL(29) = 1; same as scotch on one rank), amd
  /// (ICNTL(7) = 0) or pord (ICNTL(7) = 4).
  std::string ordering = "scotch";
  /// true: the matrix is symmetric (MUMPS sym = 2, LDLᵀ of the lower triangle, about half
  /// the work). Only for a matrix known to be symmetric; false (sym = 0, LU) is always safe.
  bool symmetric = false;
};

/// Reads the `MUMPS` sublist; throws InputError naming `where` + key on a bad value.
MumpsOptions mumps_options_from(const Teuchos::ParameterList& params, const std::string& where);

/// Counters of what the solver did (for tests and benchmarks).
struct MumpsStatistics {
  int analyses = 0;           ///< symbolic analyses (job 1): once per sparsity pattern
  int factorisations = 0;     ///< numeric factorisations (job 2), retries included
  int solves = 0;             ///< forward/backward substitutions (job 3)
  int workspace_retries = 0;  ///< factorisations repeated with more workspace (INFOG(1) -8/-9)
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

/// Debian's SCOTCH 7 orders with several threads, and their scheduling changes the ordering:
/// the same matrix got a different ordering, so different pivots and round-off, in every run
/// (3D Hertz, 1.3 k nodes, three runs: factorisation flops 3.5e8, 3.6e8 and 4.0e8,
/// displacements 1e-17 apart; with AMD, or one SCOTCH thread, bitwise the same), and its
/// random generator moves on from one analysis to the next. Called before every analysis:
/// sets SCOTCH_PTHREAD_NUMBER=1 unless the user set it, and resets SCOTCH's generator to its
/// seed. The ordering then depends on the matrix alone: the same on every run, for every
/// solver in a process, and on any number of ranks (the analysis runs on rank 0).
void make_scotch_ordering_reproducible();

/// With more than one MPI rank and OpenBLAS as the BLAS: one OpenBLAS thread per rank, unless
/// the user set OPENBLAS_NUM_THREADS (or OMP_NUM_THREADS). Ranks and BLAS threads would
/// otherwise compete for the same cores.
void limit_blas_threads_under_mpi(int num_ranks);

}  // namespace grout
