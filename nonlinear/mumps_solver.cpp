#include "nonlinear/mumps_solver.hpp"

#include <dlfcn.h>
#include <dmumps_c.h>
#include <mpi.h>
#include <scotch.h>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <algorithm>
#include <climits>
#include <cstdlib>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "assembly/raw_mpi_comm.hpp"
#include "nonlinear/mumps_numbering.hpp"
#include "nonlinear/mumps_pattern.hpp"
#include "nonlinear/mumps_schur.hpp"

namespace grout {

namespace {

bool user_set_blas_threads() {
  for (const char* user : {"OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS"})
    if (std::getenv(user)) return true;
  return false;
}

// OpenBLAS read its environment when it was loaded: its thread count is set through its API,
// found at run time (absent with another BLAS, which then keeps its own setting).
using SetThreads = void (*)(int);
using GetThreads = int (*)();
SetThreads openblas_set() {
  return reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
}
GetThreads openblas_get() {
  return reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
}

}  // namespace

void limit_blas_threads_under_mpi(int num_ranks) {
  if (num_ranks < 2 || user_set_blas_threads()) return;
  if (const auto set = openblas_set()) set(1);
}

SingleBlasThread::SingleBlasThread() {
  if (user_set_blas_threads()) return;
  const auto set = openblas_set();
  const auto get = openblas_get();
  if (!set || !get) return;
  const int threads = get();
  if (threads == 1) return;
  restore_ = threads;
  set(1);
}

SingleBlasThread::~SingleBlasThread() {
  if (restore_ > 0)
    if (const auto set = openblas_set()) set(restore_);
}

namespace {

// MUMPS documents its controls and diagnostics 1-based: ICNTL(i), INFOG(i).
MUMPS_INT& icntl(DMUMPS_STRUC_C& m, int i) {
  return m.icntl[i - 1];
}
MUMPS_INT infog(const DMUMPS_STRUC_C& m, int i) {
  return m.infog[i - 1];
}

// SCOTCH 7 (ICNTL(7) = 3, ICNTL(29) = 1) orders with several threads and draws from one
// pseudo-random generator over the whole process, so the ordering, and with it the
// factorisation's rounding, changed from run to run and from one analysis to the next of the
// same matrix (2D Hertz level 3: 9e-8 relative in displ_x between two identical 1-rank runs,
// docs/performance.md, "MUMPS as the default direct solver in 3D"). One SCOTCH thread (unless
// the user set SCOTCH_PTHREAD_NUMBER) and the generator reset to a fixed seed before every
// analysis make the ordering a function of the matrix alone. SCOTCH_randomSeed is looked up
// at run time in the SCOTCH that MUMPS loaded (absent: nothing to seed).
void make_scotch_deterministic() {
  setenv("SCOTCH_PTHREAD_NUMBER", "1", 0);
  using Seed = void (*)(SCOTCH_Num);
  if (const auto seed = reinterpret_cast<Seed>(dlsym(RTLD_DEFAULT, "SCOTCH_randomSeed"))) seed(1);
}

std::string describe(int code) {
  switch (code) {
    case -5:
    case -7:
    case -13:
      return " (out of memory)";
    case -8:
    case -9:
    case -14:
    case -15:
      return " (workspace too small)";
    case -10:
      return " (numerically singular matrix)";
    default:
      return "";
  }
}

// x_i = b_i / a_ii on every owned row whose only nonzero is its diagonal (e.g. λ_j = 0 of an
// open contact node): exact there, where the factorisation's rounding would leave ~1e-16.
void exact_diagonal_rows(const Matrix& K, const MumpsEntries& entries, const Vector& b, Vector& x) {
  const auto local = K.getLocalMatrixHost();
  const LO n_local = LO(entries.row_index.size());
  auto b_local = b.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto to = x.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (LO i = 0; i < n_local; ++i) {
    double diagonal = 0.0;
    bool only_diagonal = true;
    for (auto p = local.graph.row_map(i); p < local.graph.row_map(i + 1) && only_diagonal; ++p) {
      if (local.values(p) == 0.0) continue;
      if (entries.column_index[local.graph.entries(p)] == entries.row_index[std::size_t(i)])
        diagonal = local.values(p);
      else
        only_diagonal = false;
    }
    if (only_diagonal && diagonal != 0.0) to(i, 0) = b_local(i, 0) / diagonal;
  }
}

}  // namespace

static_assert(std::is_same<MUMPS_INT, int>::value,
              "grout::MumpsSolver: MumpsPattern keeps MUMPS's indices as int (32-bit MUMPS)");

// The MUMPS instance and what the phases keep between solves: the numbering
// (mumps_numbering.hpp), the analysed pattern (mumps_pattern.hpp), the factorised values and
// the Schur updates (mumps_schur.hpp).
struct MumpsSolver::Impl {
  MumpsOptions options;
  DMUMPS_STRUC_C m{};
  MPI_Comm comm = MPI_COMM_NULL;
  int rank = 0;
  bool initialised = false;
  bool analysed = false;
  bool factorised = false;
  bool parallel_analysis = false;  // ordering ptscotch on 2+ ranks
  MumpsStatistics stats;

  MumpsNumbering numbering;
  GO n = -1;  // global rows of the analysed pattern
  MumpsPattern pattern;
  std::vector<double> values;  // the current matrix's values in pattern order

  // Schur updates (MumpsOptions::schur_updates): the set, the base and the dense factor; MUMPS's
  // 1-based Schur list, its buffer for S(A) on rank 0, the reduced right-hand side.
  MumpsSchur schur;
  std::vector<MUMPS_INT> schur_list;
  std::vector<double> schur_buffer, reduced_rhs;

  std::vector<double> rhs;  // b, then x, on rank 0

  ~Impl() { finish(); }

  void start(MPI_Comm c, int num_ranks) {
    finish();
    limit_blas_threads_under_mpi(num_ranks);
    comm = c;
    MPI_Comm_rank(c, &rank);
    m = DMUMPS_STRUC_C{};
    m.comm_fortran = MUMPS_INT(MPI_Comm_c2f(c));
    m.par = 1;  // rank 0 works too
    m.sym = options.symmetric ? 2 : 0;
    m.job = -1;
    dmumps_c(&m);
    if (infog(m, 1) < 0)
      throw std::runtime_error("MUMPS initialisation failed: INFOG(1) = " +
                               std::to_string(infog(m, 1)));
    initialised = true;
    icntl(m, 1) = -1;  // no error, diagnostic, global-information output
    icntl(m, 2) = -1;
    icntl(m, 3) = -1;
    icntl(m, 4) = 0;
    icntl(m, 5) = 0;   // assembled matrix
    icntl(m, 18) = 3;  // distributed: each rank gives its entries
    icntl(m, 20) = 0;  // dense right-hand side on rank 0
    icntl(m, 21) = 0;  // solution returned on rank 0
    // One step of iterative refinement x += A⁻¹(b − A x) (CNTL(2): stop below a componentwise
    // backward error of 1e-15): the (u, λ) system mixes force and gap rows of very different
    // scales, and one step takes |b − A x|/|b| from ~1e-14..1e-12 to ~1e-16 for the price of
    // a matrix-vector product and a second forward/backward substitution.
    icntl(m, 10) = 1;
    m.cntl[1] = 1e-15;
    parallel_analysis = options.ordering == "ptscotch" && num_ranks > 1;
    icntl(m, 28) = 1;  // sequential analysis (parallel: set per analysis, analyse())
    icntl(m, 7) = options.ordering == "amd" ? 0 : options.ordering == "pord" ? 4 : 3;
    analysed = factorised = false;
    n = -1;
    numbering = MumpsNumbering{};  // its maps are on the previous communicator
  }

  void finish() {
    if (!initialised) return;
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) {
      m.job = -2;
      dmumps_c(&m);
    }
    initialised = analysed = factorised = false;
  }

  // Run MUMPS job `job` on the pattern and values; a negative INFOG(1) throws (the same on
  // every rank).
  void run(int job, const char* what) {
    m.irn_loc = pattern.irn.data();
    m.jcn_loc = pattern.jcn.data();
    m.a_loc = values.data();
    m.job = job;
    dmumps_c(&m);
    const int status = infog(m, 1);
    if (status < 0) {
      throw std::runtime_error(std::string("MUMPS ") + what +
                               " failed: INFOG(1) = " + std::to_string(status) +
                               ", INFOG(2) = " + std::to_string(infog(m, 2)) + describe(status));
    }
  }

  // Symbolic analysis (job 1) of the pattern of n rows with the Schur set schur.rows (none:
  // empty), MUMPS ordering that set last (centralised Schur complement on rank 0, ICNTL(19)).
  // PT-SCOTCH's parallel analysis (ICNTL(28) = 2, ICNTL(29) = 1) only without a Schur set:
  // MUMPS refuses the two together (INFOG(1) = −39); with one, SCOTCH on rank 0.
  void analyse() {
    const bool parallel = parallel_analysis && schur.rows.empty();
    icntl(m, 28) = parallel ? 2 : 1;
    if (parallel) icntl(m, 29) = 1;
    schur_list.resize(schur.rows.size());
    for (std::size_t k = 0; k < schur.rows.size(); ++k)
      schur_list[k] = MUMPS_INT(schur.rows[k] + 1);
    icntl(m, 19) = schur.rows.empty() ? 0 : 1;
    m.size_schur = MUMPS_INT(schur.rows.size());
    m.listvar_schur = schur_list.empty() ? nullptr : schur_list.data();
    stats.schur_size = int(schur.rows.size());
    m.n = MUMPS_INT(n);
    m.nz_loc = MUMPS_INT(pattern.irn.size());
    m.nnz_loc = MUMPS_INT8(pattern.irn.size());
    make_scotch_deterministic();
    run(1, "analysis");
    ++stats.analyses;
    analysed = true;
  }

  // Numeric factorisation (job 2); on a workspace shortfall (INFOG(1) = -8 or -9) raise the
  // workspace relaxation ICNTL(14) (percent over the analysis estimate) and retry. With a
  // Schur set MUMPS writes S(A) into schur_buffer on rank 0.
  void factorise_values() {
    for (int attempt = 0;; ++attempt) {
      if (!schur.rows.empty() && rank == 0) {
        schur_buffer = DenseSchur::prepare(int(schur.rows.size()));
        m.schur = schur_buffer.data();
        m.schur_lld = MUMPS_INT(schur.rows.size());
      }
      m.irn_loc = pattern.irn.data();
      m.jcn_loc = pattern.jcn.data();
      m.a_loc = values.data();
      m.job = 2;
      dmumps_c(&m);
      ++stats.factorisations;
      const int status = infog(m, 1);
      if ((status == -8 || status == -9) && attempt < 6) {
        icntl(m, 14) = 2 * std::max<MUMPS_INT>(icntl(m, 14), 20);
        ++stats.workspace_retries;
        continue;
      }
      if (status < 0) {
        factorised = false;
        throw std::runtime_error(
            "MUMPS factorisation failed: INFOG(1) = " + std::to_string(status) +
            ", INFOG(2) = " + std::to_string(infog(m, 2)) + describe(status));
      }
      factorised = true;
      stats.flops = m.rinfog[2];
      stats.factor_entries = infog(m, 29);
      const double nb = double(schur.rows.size());
      schur.full_flops = stats.flops + nb * nb * nb / 3.0;
      return;
    }
  }

  // After a sparse factorisation with a Schur set: S(A) to the dense solver on rank 0 and its
  // Cholesky factorisation; false (on every rank) if S(A) is not positive definite.
  bool take_schur() {
    int ok = 1;
    if (!schur.rows.empty() && rank == 0)
      ok = int(schur.dense.set_base(int(schur.rows.size()), schur_buffer));
    std::vector<double>().swap(schur_buffer);  // now the previous base: released
    MPI_Bcast(&ok, 1, MPI_INT, 0, comm);
    return ok != 0;
  }

  // The factorisation of the current values, which become the Schur updates' base. S(A) not
  // positive definite (A is not): analysed and factorised again without a Schur set.
  void factorise() {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: MUMPS factorisation"));
    factorise_values();
    if (!take_schur()) {
      schur.rows.clear();
      analyse();
      factorise_values();
    }
    schur.base_values = values;
  }

  // Forward and backward substitution (job 3) of the right-hand side `rhs` on rank 0, which it
  // overwrites with the solution. With a Schur set: reduction (forward substitution on the
  // interior, the reduced right-hand side on the Schur rows), the dense solve there, expansion
  // (ICNTL(26) = 1, 2). MUMPS does no iterative refinement with a Schur complement; the matrix
  // is SPD (LDLᵀ of a reduced elastic stiffness), where one is not needed.
  void substitute() {
    const bool is_root = rank == 0;
    m.rhs = is_root ? rhs.data() : nullptr;
    m.nrhs = 1;
    m.lrhs = MUMPS_INT(n);
    if (schur.rows.empty()) {
      run(3, "solve");
    } else {
      const MUMPS_INT nb = MUMPS_INT(schur.rows.size());
      reduced_rhs.assign(is_root ? std::size_t(nb) : 0, 0.0);
      m.redrhs = is_root ? reduced_rhs.data() : nullptr;
      m.lredrhs = nb;
      icntl(m, 10) = 0;
      icntl(m, 26) = 1;
      run(3, "solve (reduction)");
      if (is_root) schur.dense.solve(reduced_rhs.data());
      icntl(m, 26) = 2;
      run(3, "solve (expansion)");
      icntl(m, 26) = 0;
      icntl(m, 10) = 1;
    }
    ++stats.solves;
  }
};

MumpsSolver::MumpsSolver(MumpsOptions options) : impl_(std::make_unique<Impl>()) {
  impl_->options = std::move(options);
}

MumpsSolver::~MumpsSolver() = default;

const MumpsStatistics& MumpsSolver::statistics() const {
  return impl_->stats;
}

// The phases: numbering (mumps_numbering.hpp), pattern and analysis while it holds
// (mumps_pattern.hpp), the numeric factorisation or a Schur update (mumps_schur.hpp), the
// solve.
void MumpsSolver::solve(const Teuchos::RCP<const Matrix>& K, const Vector& b, Vector& x) {
  Impl& s = *impl_;
  const auto& comm = *K->getRowMap()->getComm();
  const MPI_Comm mpi_comm = raw_mpi_comm(comm);
  if (!s.initialised || s.comm != mpi_comm) s.start(mpi_comm, comm.getSize());

  const auto row_map = K->getRowMap();
  const LO n_local = LO(row_map->getNodeNumElements());
  const GO n = GO(row_map->getGlobalNumElements());
  if (n >= GO(INT_MAX)) throw std::runtime_error("MUMPS: more than 2^31 unknowns");
  if (LO(b.getLocalLength()) != n_local || LO(x.getLocalLength()) != n_local)
    throw std::logic_error("MumpsSolver::solve: b and x must be on the matrix's row map");

  // Numbering: rebuilt only when the layout changes; the analysed pattern is in the old one.
  if (renumber(s.numbering, row_map, mpi_comm)) s.analysed = false;
  MumpsEntries entries = mumps_entries(s.numbering, *K, s.options.symmetric);

  // Pattern: analysed again only when the matrix has an entry outside it (on any rank).
  const bool valid = s.analysed && s.n == n;
  const bool missing =
      pattern_misses(s.pattern, valid, entries.keys, entries.sorted_prefix, mpi_comm);
  // Schur updates: the last factorised matrix (pattern and values) is the base. On any number
  // of ranks: on 2, MUMPS's centralised Schur complement (ICNTL(19) = 1) and the dense update
  // run on rank 0 alone and the set is reused for 2 of 7 iterations on the 11.0 k-node spheres
  // (5 analyses), yet the run takes 0.86x the wall time of refactorising every time on a quiet
  // machine (docs/performance.md, "Condensed, symmetric and
  // Schur-updated direct solves").
  const bool have_base = s.options.symmetric && s.options.schur_updates && valid && s.factorised &&
                         !s.schur.base_values.empty();
  std::vector<long long> base_keys;
  if (have_base && missing) base_keys = s.pattern.keys;
  if (missing) rebuild_pattern(s.pattern, valid, entries.keys, entries.sorted_prefix, n, mpi_comm);
  s.pattern.last_keys.swap(entries.keys);

  // Values: factorised again when they changed (on any rank).
  std::vector<double> values = values_in_pattern(s.pattern, entries.values);
  int changed = int(missing || !s.factorised || values != s.values);
  MPI_Allreduce(MPI_IN_PLACE, &changed, 1, MPI_INT, MPI_MAX, mpi_comm);
  s.values.swap(values);
  std::vector<long long> rows;  // the rows whose entries differ from the base's (any rank)
  if (have_base && changed)
    rows = rows_changed_on_any_rank(missing ? base_keys : s.pattern.keys, s.schur.base_values,
                                    s.pattern.keys, s.values, n, mpi_comm);
  const bool changed_before = note_changed_rows(s.schur, rows, have_base);

  if (missing) {
    s.schur.rows = next_schur_set(s.schur, rows, changed_before);
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: MUMPS analysis"));
    s.n = n;
    s.analysed = s.factorised = false;
    s.analyse();
  }
  bool updated = false;
  if (changed && !missing && have_base && !s.schur.rows.empty() &&
      rows_within(rows, s.schur.rows)) {
    // Only rows of the Schur set changed: S(A') = S(A) + (A' − A)_BB, dense Cholesky.
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: MUMPS Schur update"));
    updated = update_schur(s.schur, s.pattern, s.values, n, mpi_comm);
    if (updated) ++s.stats.schur_updates;  // else not positive definite: factorised below
  }
  if (changed && !updated) s.factorise();

  // Solve with b gathered on rank 0; x scattered back.
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: MUMPS solve"));
  s.rhs = gather_to_root(s.numbering, b);
  s.substitute();
  scatter_from_root(s.numbering, s.rhs, x);
  exact_diagonal_rows(*K, entries, b, x);
}

}  // namespace grout
