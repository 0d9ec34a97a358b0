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
#include <iterator>
#include <stdexcept>
#include <vector>

#include "assembly/raw_mpi_comm.hpp"
#include "io/errors.hpp"
#include "nonlinear/schur_update.hpp"

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

// The position in `pattern` (sorted, unique) of every key; false if a key is not in it.
// The increasing keys[0 .. sorted) are found in one forward walk, the others by binary search.
bool locate(const std::vector<long long>& pattern, const std::vector<long long>& keys,
            std::size_t sorted, std::vector<std::size_t>& position) {
  position.assign(keys.size(), 0);
  auto it = pattern.begin();
  for (std::size_t k = 0; k < keys.size(); ++k) {
    if (k < sorted) {
      while (it != pattern.end() && *it < keys[k]) ++it;
    } else {
      it = std::lower_bound(pattern.begin(), pattern.end(), keys[k]);
    }
    if (it == pattern.end() || *it != keys[k]) return false;
    position[k] = std::size_t(it - pattern.begin());
  }
  return true;
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

// The union over all ranks of sorted 0-based row lists (the same sorted list on every rank).
std::vector<long long> union_over_ranks(const std::vector<long long>& local, MPI_Comm comm) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  if (ranks == 1) return local;
  int count = int(local.size());
  std::vector<int> counts(static_cast<std::size_t>(ranks), 0), offsets(counts);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int r = 1; r < ranks; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<long long> all(std::size_t(offsets.back() + counts.back()));
  MPI_Allgatherv(local.data(), count, MPI_LONG_LONG, all.data(), counts.data(), offsets.data(),
                 MPI_LONG_LONG, comm);
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

// Every rank's Schur deltas on rank 0 (as triplets of doubles: i, j, value).
std::vector<SchurDelta> gather_deltas(const std::vector<SchurDelta>& local, MPI_Comm comm) {
  int ranks = 1, rank = 0;
  MPI_Comm_size(comm, &ranks);
  MPI_Comm_rank(comm, &rank);
  if (ranks == 1) return local;
  std::vector<double> packed;
  for (const SchurDelta& d : local)
    packed.insert(packed.end(), {double(d.i), double(d.j), d.value});
  int count = int(packed.size());
  std::vector<int> counts(static_cast<std::size_t>(ranks), 0), offsets(counts);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  for (int r = 1; r < ranks; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<double> all(rank == 0 ? std::size_t(offsets.back() + counts.back()) : 0);
  MPI_Gatherv(packed.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
              MPI_DOUBLE, 0, comm);
  std::vector<SchurDelta> deltas;
  for (std::size_t k = 0; k + 2 < all.size(); k += 3)
    deltas.push_back({int(all[k]), int(all[k + 1]), all[k + 2]});
  return deltas;
}

}  // namespace

struct MumpsSolver::Impl {
  MumpsOptions options;
  DMUMPS_STRUC_C m{};
  MPI_Comm comm = MPI_COMM_NULL;
  int rank = 0;
  bool initialised = false;
  bool analysed = false;
  bool factorised = false;
  MumpsStatistics stats;

  // The analysed pattern on this rank: sorted keys row * n + col (0-based, MUMPS
  // numbering) and MUMPS's 1-based irn, jcn; the values in that order; the matrix entries'
  // positions in it, and their keys at the last solve (to skip the search when unchanged).
  GO n = -1;
  std::vector<long long> pattern, last_keys;
  std::vector<std::size_t> position;
  std::vector<MUMPS_INT> irn, jcn;
  std::vector<double> values;

  // Schur updates (MumpsOptions::schur_updates, schur_update.hpp): the Schur set B of the
  // last analysis (sorted 0-based rows; MUMPS's 1-based list), the values of the last
  // factorised matrix (in `pattern` order), its flops with the Schur block's Cholesky, and on
  // rank 0 the dense Schur complement with the factor of the current matrix.
  std::vector<long long> schur_rows, changed_ever;
  std::vector<MUMPS_INT> schur_list;
  std::vector<double> base_values, schur_buffer, reduced_rhs;
  double full_flops = 0.0;
  DenseSchur dense;

  // b gathered to rank 0 and x scattered back: `source` is the row map (global-id numbering)
  // or its contiguous renumbering.
  bool gid_numbering = false;
  Teuchos::RCP<const Map> source, root;
  Teuchos::RCP<Export> to_root;
  std::vector<double> rhs;

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
    if (options.ordering == "ptscotch" && num_ranks > 1) {
      icntl(m, 28) = 2;  // parallel analysis
      icntl(m, 29) = 1;  // PT-SCOTCH
    } else {
      icntl(m, 28) = 1;  // sequential analysis
      icntl(m, 7) = options.ordering == "amd" ? 0 : options.ordering == "pord" ? 4 : 3;
    }
    analysed = factorised = false;
    n = -1;
  }

  // The Schur set for the next analysis (0: none); MUMPS orders those rows last.
  void configure_schur() {
    schur_list.resize(schur_rows.size());
    for (std::size_t k = 0; k < schur_rows.size(); ++k)
      schur_list[k] = MUMPS_INT(schur_rows[k] + 1);
    icntl(m, 19) = schur_rows.empty() ? 0 : 1;  // centralised Schur complement on rank 0
    m.size_schur = MUMPS_INT(schur_rows.size());
    m.listvar_schur = schur_list.empty() ? nullptr : schur_list.data();
    stats.schur_size = int(schur_rows.size());
  }

  // After a sparse factorisation with a Schur set: S(A) to the dense solver on rank 0 and its
  // Cholesky factorisation; false (on every rank) if S(A) is not positive definite.
  bool take_schur(MPI_Comm c) {
    int ok = 1;
    if (!schur_rows.empty() && rank == 0)
      ok = int(dense.set_base(int(schur_rows.size()), schur_buffer));
    std::vector<double>().swap(schur_buffer);  // now the previous base: released
    MPI_Bcast(&ok, 1, MPI_INT, 0, c);
    return ok != 0;
  }

  // Whether a Schur set of `size` rows pays: its dense Cholesky factorisation (size³/3 flops)
  // at most half the last sparse factorisation (with its Schur block), and at most 6000 rows
  // (288 MB per dense copy).
  bool schur_pays(std::size_t size) const {
    const double nb = double(size);
    return size > 0 && size <= 6000 && nb * nb * nb / 3.0 <= 0.5 * full_flops;
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

  // Run MUMPS job `job`; a negative INFOG(1) throws (the same on every rank).
  void run(int job, const char* what) {
    m.irn_loc = irn.data();
    m.jcn_loc = jcn.data();
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

  // Numeric factorisation; on a workspace shortfall (INFOG(1) = -8 or -9) raise the
  // workspace relaxation ICNTL(14) (percent over the analysis estimate) and retry.
  void factorise() {
    for (int attempt = 0;; ++attempt) {
      if (!schur_rows.empty() && rank == 0) {
        schur_buffer = DenseSchur::prepare(int(schur_rows.size()));
        m.schur = schur_buffer.data();
        m.schur_lld = MUMPS_INT(schur_rows.size());
      }
      m.irn_loc = irn.data();
      m.jcn_loc = jcn.data();
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
      const double nb = double(schur_rows.size());
      full_flops = stats.flops + nb * nb * nb / 3.0;
      return;
    }
  }
};

MumpsSolver::MumpsSolver(MumpsOptions options) : impl_(std::make_unique<Impl>()) {
  impl_->options = std::move(options);
}

MumpsSolver::~MumpsSolver() = default;

const MumpsStatistics& MumpsSolver::statistics() const {
  return impl_->stats;
}

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

  // MUMPS's numbering. When the row map's global ids are 0 .. n-1 (Grout's maps: node * dim
  // + component, then the multipliers in slave-node order), they are used as they are: the
  // matrix MUMPS sees, and so its ordering and pivot sequence, is then the same on any number
  // of ranks. Otherwise a contiguous renumbering (this rank's rows offset .. offset + n_local
  // - 1, in the row map's local order). Rebuilt only when the layout changes.
  const bool gid_numbering = row_map->getMinAllGlobalIndex() == 0 &&
                             row_map->getMaxAllGlobalIndex() == n - 1 && row_map->isOneToOne();
  int same_layout = s.source.is_null()
                        ? 0
                        : int(s.n == n && s.gid_numbering == gid_numbering &&
                              (gid_numbering ? s.source->isSameAs(*row_map)
                                             : LO(s.source->getNodeNumElements()) == n_local));
  MPI_Allreduce(MPI_IN_PLACE, &same_layout, 1, MPI_INT, MPI_MIN, mpi_comm);
  if (!same_layout) {
    s.gid_numbering = gid_numbering;
    s.source =
        gid_numbering
            ? row_map
            : Teuchos::RCP<const Map>(new Map(n, std::size_t(n_local), 0, row_map->getComm()));
    s.root =
        Teuchos::rcp(new Map(n, std::size_t(comm.getRank() == 0 ? n : 0), 0, row_map->getComm()));
    s.to_root = Teuchos::rcp(new Export(s.source, s.root));
    // The analysed pattern is in the old numbering.
    s.analysed = false;
  }

  // MUMPS index (0-based) of every owned row and of every column of K.
  std::vector<long long> row_index(std::size_t(n_local), 0);
  std::vector<long long> column_index(K->getColMap()->getNodeNumElements());
  if (gid_numbering) {
    for (LO i = 0; i < n_local; ++i) row_index[std::size_t(i)] = row_map->getGlobalElement(i);
    const auto& col_map = *K->getColMap();
    for (std::size_t j = 0; j < column_index.size(); ++j)
      column_index[j] = col_map.getGlobalElement(LO(j));
  } else {
    const GO offset = s.source->getMinGlobalIndex();
    for (LO i = 0; i < n_local; ++i) row_index[std::size_t(i)] = offset + i;
    // The owned rows' indices imported to the columns.
    Vector row_values(row_map), col_values(K->getColMap());
    {
      auto r = row_values.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (LO i = 0; i < n_local; ++i) r(i, 0) = double(offset + i);
    }
    const auto importer = K->getGraph()->getImporter();
    if (!importer.is_null() && K->getDomainMap()->isSameAs(*row_map)) {
      col_values.doImport(row_values, *importer, Tpetra::INSERT);
    } else {
      col_values.doImport(row_values, Import(row_map, K->getColMap()), Tpetra::INSERT);
    }
    auto c = col_values.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t j = 0; j < column_index.size(); ++j) column_index[j] = (long long)(c(j, 0));
  }

  // This rank's entries (lower triangle only when symmetric) as keys row * n + col (0-based
  // MUMPS numbering), in the matrix's storage order.
  const auto local = K->getLocalMatrixHost();
  std::vector<long long> keys, mirror_keys;
  std::vector<double> entry_values;
  keys.reserve(local.nnz());
  entry_values.reserve(local.nnz());
  for (LO i = 0; i < n_local; ++i) {
    const long long row = row_index[std::size_t(i)];
    for (auto p = local.graph.row_map(i); p < local.graph.row_map(i + 1); ++p) {
      const long long col = column_index[local.graph.entries(p)];
      if (s.options.symmetric && col > row) {
        // An explicit zero above the diagonal stands for its mirror's place in the pattern
        // (symmetric_condensation.hpp keeps the pattern of rows it eliminates that way, on
        // the rank owning the row only): it adds the lower key (col, row) and nothing to the
        // values. Those keys go last, after the rows' own (in row order, on one rank sorted:
        // found in one forward walk below instead of a binary search each).
        if (local.values(p) == 0.0) mirror_keys.push_back(col * n + row);
        continue;
      }
      keys.push_back(row * n + col);
      entry_values.push_back(local.values(p));
    }
  }
  keys.insert(keys.end(), mirror_keys.begin(), mirror_keys.end());
  entry_values.resize(keys.size(), 0.0);

  // The analysed pattern is kept while the matrix's pattern stays inside it: the Jacobian's
  // pattern follows the contact state (active set, mortar pairs, nonzero derivatives) and
  // changes between Newton iterations, mostly within what earlier iterations had. Entries
  // of the analysed pattern that the matrix lacks are explicit zeros. A new entry leads to
  // a new analysis of the union of both patterns, or of the new pattern alone if the union
  // would be more than twice its size.
  // Keys in increasing order (the gathered matrix: rows in order, each row's columns in
  // order) are looked up in one forward walk and need no sort.
  const std::size_t sorted_prefix =
      std::size_t(std::is_sorted_until(keys.begin(), keys.end()) - keys.begin());
  const bool keys_sorted = sorted_prefix == keys.size();
  int missing = 0;
  if (!(s.analysed && s.n == n && keys == s.last_keys))
    missing = int(!(s.analysed && s.n == n && locate(s.pattern, keys, sorted_prefix, s.position)));
  MPI_Allreduce(MPI_IN_PLACE, &missing, 1, MPI_INT, MPI_MAX, mpi_comm);
  // Schur updates: the last factorised matrix (pattern and values) is the base. On any number
  // of ranks: on 2, MUMPS's centralised Schur complement (ICNTL(19) = 1) and the dense update
  // run on rank 0 alone and the set is reused for 2 of 7 iterations on the 11.0 k-node spheres
  // (5 analyses), yet the run takes 0.86x the wall time of refactorising every time on a quiet
  // machine (docs/performance.md, "Condensed, symmetric and
  // Schur-updated direct solves").
  const bool updates = s.options.symmetric && s.options.schur_updates;
  const bool have_base =
      updates && s.analysed && s.factorised && s.n == n && !s.base_values.empty();
  std::vector<long long> base_pattern;
  if (have_base && missing) base_pattern = s.pattern;
  if (missing) {
    std::vector<long long> sorted = keys;
    if (!keys_sorted) {  // the unsorted tail sorted, then merged with the sorted prefix
      const auto middle = sorted.begin() + std::ptrdiff_t(sorted_prefix);
      std::sort(middle, sorted.end());
      std::inplace_merge(sorted.begin(), middle, sorted.end());
    }
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    std::vector<long long> merged;
    if (s.analysed && s.n == n) {
      std::set_union(s.pattern.begin(), s.pattern.end(), sorted.begin(), sorted.end(),
                     std::back_inserter(merged));
    }
    int use_union = int(!merged.empty() && merged.size() <= 2 * sorted.size());
    MPI_Allreduce(MPI_IN_PLACE, &use_union, 1, MPI_INT, MPI_MIN, mpi_comm);
    s.pattern = use_union ? std::move(merged) : std::move(sorted);
    s.irn.resize(s.pattern.size());
    s.jcn.resize(s.pattern.size());
    for (std::size_t e = 0; e < s.pattern.size(); ++e) {
      s.irn[e] = MUMPS_INT(s.pattern[e] / n) + 1;
      s.jcn[e] = MUMPS_INT(s.pattern[e] % n) + 1;
    }
    locate(s.pattern, keys, sorted_prefix, s.position);
  }
  s.last_keys.swap(keys);

  std::vector<double> values(s.pattern.size(), 0.0);
  for (std::size_t k = 0; k < entry_values.size(); ++k) values[s.position[k]] += entry_values[k];
  int changed[2] = {missing, 0};
  changed[1] = int(missing || !s.factorised || values != s.values);
  MPI_Allreduce(MPI_IN_PLACE, &changed[1], 1, MPI_INT, MPI_MAX, mpi_comm);
  s.values.swap(values);
  // The rows whose entries differ from the base's (any rank).
  std::vector<long long> rows;
  if (have_base && changed[1])
    rows = union_over_ranks(
        changed_rows(missing ? base_pattern : s.pattern, s.base_values, s.pattern, s.values, n),
        mpi_comm);
  // Every row changed so far (since the first factorisation of this layout).
  const bool changed_before = have_base && !s.changed_ever.empty();
  if (!have_base) s.changed_ever.clear();
  {
    std::vector<long long> joined;
    std::set_union(s.changed_ever.begin(), s.changed_ever.end(), rows.begin(), rows.end(),
                   std::back_inserter(joined));
    s.changed_ever.swap(joined);
  }

  if (changed[0]) {
    // A new Schur set, at an analysis the pattern asks for anyway (so never an extra one):
    // every row changed so far (rows that changed once change again in the next Newton
    // iterations), or those changed since the last factorisation, or none. Not at the first
    // change: a factorisation with a Schur set costs more than one without (MUMPS orders the
    // set last; 1.6–1.9× the flops on the 3D Hertz spheres), which pays only if the set is
    // reused, and a single change is no evidence that the rows keep changing.
    s.schur_rows = !changed_before                       ? std::vector<long long>{}
                   : s.schur_pays(s.changed_ever.size()) ? s.changed_ever
                   : s.schur_pays(rows.size())           ? rows
                                                         : std::vector<long long>{};
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: MUMPS analysis"));
    s.n = n;
    s.analysed = s.factorised = false;
    s.m.n = MUMPS_INT(n);
    s.m.nz_loc = MUMPS_INT(s.irn.size());
    s.m.nnz_loc = MUMPS_INT8(s.irn.size());
    s.configure_schur();
    make_scotch_deterministic();
    s.run(1, "analysis");
    ++s.stats.analyses;
    s.analysed = true;
  }
  bool updated = false;
  if (changed[1] && !changed[0] && have_base && !s.schur_rows.empty() &&
      rows_within(rows, s.schur_rows)) {
    // Only rows of the Schur set changed: S(A') = S(A) + (A' − A)_BB, dense Cholesky.
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: MUMPS Schur update"));
    std::vector<int> where(std::size_t(n), -1);
    for (std::size_t k = 0; k < s.schur_rows.size(); ++k)
      where[std::size_t(s.schur_rows[k])] = int(k);
    std::vector<SchurDelta> deltas;
    for (std::size_t p = 0; p < s.pattern.size(); ++p) {
      const double d = s.values[p] - s.base_values[p];
      if (d == 0.0) continue;
      const int i = where[std::size_t(s.pattern[p] / n)], j = where[std::size_t(s.pattern[p] % n)];
      if (i >= 0 && j >= 0) deltas.push_back({i, j, d});
    }
    deltas = gather_deltas(deltas, mpi_comm);
    int ok = comm.getRank() == 0 ? int(s.dense.update(deltas)) : 1;
    MPI_Bcast(&ok, 1, MPI_INT, 0, mpi_comm);
    updated = ok != 0;  // not positive definite: factorise below instead
    if (updated) ++s.stats.schur_updates;
  }
  if (changed[1] && !updated) {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: MUMPS factorisation"));
    s.factorise();
    if (!s.take_schur(mpi_comm)) {
      // S(A) not positive definite (A is not): analyse and factorise without a Schur set.
      s.schur_rows.clear();
      s.configure_schur();
      make_scotch_deterministic();
      s.run(1, "analysis");
      ++s.stats.analyses;
      s.factorise();
    }
    s.base_values = s.values;
  }

  // Solve with b gathered on rank 0; scatter x back.
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: MUMPS solve"));
  Vector b_source(s.source), b_root(s.root);
  {
    auto from = b.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto to = b_source.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (LO i = 0; i < n_local; ++i) to(i, 0) = from(i, 0);
  }
  b_root.doExport(b_source, *s.to_root, Tpetra::INSERT);
  const bool is_root = comm.getRank() == 0;
  if (is_root) {
    auto r = b_root.getLocalViewHost(Tpetra::Access::ReadOnly);
    s.rhs.assign(std::size_t(n), 0.0);
    for (GO i = 0; i < n; ++i) s.rhs[std::size_t(i)] = r(i, 0);
  }
  s.m.rhs = is_root ? s.rhs.data() : nullptr;
  s.m.nrhs = 1;
  s.m.lrhs = MUMPS_INT(n);
  if (s.schur_rows.empty()) {
    s.run(3, "solve");
  } else {
    // Reduction (forward substitution on the interior, the reduced right-hand side on the
    // Schur rows), the dense solve there, expansion (ICNTL(26) = 1, 2). MUMPS does no
    // iterative refinement with a Schur complement; the matrix is SPD (LDLᵀ of a reduced
    // elastic stiffness), where one is not needed.
    const MUMPS_INT nb = MUMPS_INT(s.schur_rows.size());
    s.reduced_rhs.assign(is_root ? std::size_t(nb) : 0, 0.0);
    s.m.redrhs = is_root ? s.reduced_rhs.data() : nullptr;
    s.m.lredrhs = nb;
    icntl(s.m, 10) = 0;
    icntl(s.m, 26) = 1;
    s.run(3, "solve (reduction)");
    if (is_root) s.dense.solve(s.reduced_rhs.data());
    icntl(s.m, 26) = 2;
    s.run(3, "solve (expansion)");
    icntl(s.m, 26) = 0;
    icntl(s.m, 10) = 1;
  }
  ++s.stats.solves;
  if (is_root) {
    auto r = b_root.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (GO i = 0; i < n; ++i) r(i, 0) = s.rhs[std::size_t(i)];
  }
  b_source.doImport(b_root, *s.to_root, Tpetra::INSERT);
  auto from = b_source.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto to = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (LO i = 0; i < n_local; ++i) to(i, 0) = from(i, 0);
  // A row whose only nonzero is its diagonal (e.g. λ_j = 0 of an open contact node) fixes
  // x_i = b_i / a_ii exactly; the factorisation's rounding would leave ~1e-16 there.
  auto b_local = b.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (LO i = 0; i < n_local; ++i) {
    double diagonal = 0.0;
    bool only_diagonal = true;
    for (auto p = local.graph.row_map(i); p < local.graph.row_map(i + 1) && only_diagonal; ++p) {
      if (local.values(p) == 0.0) continue;
      if (column_index[local.graph.entries(p)] == row_index[std::size_t(i)])
        diagonal = local.values(p);
      else
        only_diagonal = false;
    }
    if (only_diagonal && diagonal != 0.0) to(i, 0) = b_local(i, 0) / diagonal;
  }
}

}  // namespace grout
