#include "nonlinear/mumps_numbering.hpp"

#include <algorithm>
#include <numeric>

#include "assembly/raw_mpi_comm.hpp"

namespace grout {

namespace {

// Values on K's rows (its row map) imported to its columns (its column map): K's own
// importer where the domain map is the row map, else one built from the two maps.
void import_to_columns(const Matrix& K, const Vector& on_rows, Vector& on_columns) {
  const auto importer = K.getGraph()->getImporter();
  if (!importer.is_null() && K.getDomainMap()->isSameAs(*K.getRowMap())) {
    on_columns.doImport(on_rows, *importer, Tpetra::INSERT);
  } else {
    on_columns.doImport(on_rows, Import(K.getRowMap(), K.getColMap()), Tpetra::INSERT);
  }
}

// The rank owning each column of K (K's column map's local order): the ranks imported from
// the row map, as the column indices are above.
std::vector<int> column_owners(const Matrix& K) {
  const auto row_map = K.getRowMap();
  Vector owner_on_rows(row_map), owner_on_columns(K.getColMap());
  owner_on_rows.putScalar(double(row_map->getComm()->getRank()));
  import_to_columns(K, owner_on_rows, owner_on_columns);
  auto c = owner_on_columns.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<int> owners(c.extent(0));
  for (std::size_t j = 0; j < owners.size(); ++j) owners[j] = int(c(j, 0));
  return owners;
}

// Each of `keys` sent to the rank owners[k] and appended there to `received`, with the keys
// the other ranks send here. Collective.
void send_to_owners(const Comm& comm, const std::vector<int>& owners,
                    const std::vector<long long>& keys, std::vector<long long>& received) {
  const int ranks = comm.getSize();
  std::vector<int> send_counts(std::size_t(ranks), 0), recv_counts(send_counts);
  for (const int owner : owners) ++send_counts[std::size_t(owner)];
  std::vector<int> send_offsets(std::size_t(ranks), 0), recv_offsets(send_offsets);
  for (std::size_t r = 1; r < send_offsets.size(); ++r)
    send_offsets[r] = send_offsets[r - 1] + send_counts[r - 1];
  std::vector<long long> ordered(keys.size());
  std::vector<int> next = send_offsets;
  for (std::size_t k = 0; k < keys.size(); ++k)
    ordered[std::size_t(next[std::size_t(owners[k])]++)] = keys[k];
  const MPI_Comm mpi_comm = raw_mpi_comm(comm);
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, mpi_comm);
  for (std::size_t r = 1; r < recv_offsets.size(); ++r)
    recv_offsets[r] = recv_offsets[r - 1] + recv_counts[r - 1];
  const std::size_t old_size = received.size();
  received.resize(old_size + std::size_t(recv_offsets.back() + recv_counts.back()));
  MPI_Alltoallv(ordered.data(), send_counts.data(), send_offsets.data(), MPI_LONG_LONG,
                received.data() + old_size, recv_counts.data(), recv_offsets.data(), MPI_LONG_LONG,
                mpi_comm);
}

}  // namespace

bool renumber(MumpsNumbering& numbering, const Teuchos::RCP<const Map>& row_map, MPI_Comm comm) {
  const LO n_local = LO(row_map->getNodeNumElements());
  const GO n = GO(row_map->getGlobalNumElements());
  const bool gid_numbering = row_map->getMinAllGlobalIndex() == 0 &&
                             row_map->getMaxAllGlobalIndex() == n - 1 && row_map->isOneToOne();
  MumpsNumbering& s = numbering;
  int same_layout = s.source.is_null()
                        ? 0
                        : int(s.n == n && s.gid_numbering == gid_numbering &&
                              (gid_numbering ? s.source->isSameAs(*row_map)
                                             : LO(s.source->getNodeNumElements()) == n_local));
  MPI_Allreduce(MPI_IN_PLACE, &same_layout, 1, MPI_INT, MPI_MIN, comm);
  if (same_layout) return false;
  const auto& tcomm = row_map->getComm();
  s.n = n;
  s.gid_numbering = gid_numbering;
  s.source =
      gid_numbering ? row_map : Teuchos::RCP<const Map>(new Map(n, std::size_t(n_local), 0, tcomm));
  s.root = Teuchos::rcp(new Map(n, std::size_t(tcomm->getRank() == 0 ? n : 0), 0, tcomm));
  s.to_root = Teuchos::rcp(new Export(s.source, s.root));
  return true;
}

MumpsEntries mumps_entries(const MumpsNumbering& numbering, const Matrix& K, bool symmetric) {
  const auto row_map = K.getRowMap();
  const LO n_local = LO(row_map->getNodeNumElements());
  const GO n = numbering.n;
  MumpsEntries e;
  // MUMPS index (0-based) of every owned row and of every column of K.
  e.row_index.assign(std::size_t(n_local), 0);
  e.column_index.assign(K.getColMap()->getNodeNumElements(), 0);
  if (numbering.gid_numbering) {
    for (LO i = 0; i < n_local; ++i) e.row_index[std::size_t(i)] = row_map->getGlobalElement(i);
    const auto& col_map = *K.getColMap();
    for (std::size_t j = 0; j < e.column_index.size(); ++j)
      e.column_index[j] = col_map.getGlobalElement(LO(j));
  } else {
    const GO offset = numbering.source->getMinGlobalIndex();
    for (LO i = 0; i < n_local; ++i) e.row_index[std::size_t(i)] = offset + i;
    // The owned rows' indices imported to the columns.
    Vector row_values(row_map), col_values(K.getColMap());
    {
      auto r = row_values.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (LO i = 0; i < n_local; ++i) r(i, 0) = double(offset + i);
    }
    import_to_columns(K, row_values, col_values);
    auto c = col_values.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t j = 0; j < e.column_index.size(); ++j)
      e.column_index[j] = (long long)(c(j, 0));
  }

  const auto local = K.getLocalMatrixHost();
  const auto& comm = *row_map->getComm();
  const int rank = comm.getRank();
  const bool distributed = symmetric && comm.getSize() > 1;
  const std::vector<int> owner = distributed ? column_owners(K) : std::vector<int>();
  std::vector<long long> mirror_keys, foreign_keys;
  std::vector<int> foreign_owners;
  e.keys.reserve(local.nnz());
  e.values.reserve(local.nnz());
  // Rows in increasing MUMPS index, each row's keys increasing: the keys then come sorted but
  // for the mirror keys, on any number of ranks. On 2 ranks the local rows and a row's
  // columns (owned first, then the other ranks') are not in MUMPS's order, and the analysed
  // pattern was then searched key by key (binary search) and sorted at every analysis
  // (mumps_pattern.hpp). A row's entries are unique keys: the values do not depend on the order.
  std::vector<LO> row_order(static_cast<std::size_t>(n_local));
  std::iota(row_order.begin(), row_order.end(), LO(0));
  if (!std::is_sorted(e.row_index.begin(), e.row_index.end()))
    std::sort(row_order.begin(), row_order.end(), [&](LO a, LO b) {
      return e.row_index[std::size_t(a)] < e.row_index[std::size_t(b)];
    });
  std::vector<std::pair<long long, double>> row_entries;
  for (const LO i : row_order) {
    const long long row = e.row_index[std::size_t(i)];
    const std::size_t first = e.keys.size();
    for (auto p = local.graph.row_map(i); p < local.graph.row_map(i + 1); ++p) {
      const LO j = local.graph.entries(p);
      const long long col = e.column_index[std::size_t(j)];
      if (symmetric && col > row) {
        // The mirror keys go last, after the rows' own (sorted: found in one forward walk
        // instead of a binary search each; mumps_pattern.hpp), on the rank owning their row.
        if (local.values(p) != 0.0) continue;
        if (!distributed || owner[std::size_t(j)] == rank) {
          mirror_keys.push_back(col * n + row);
        } else {
          foreign_keys.push_back(col * n + row);
          foreign_owners.push_back(owner[std::size_t(j)]);
        }
        continue;
      }
      e.keys.push_back(row * n + col);
      e.values.push_back(local.values(p));
    }
    if (!std::is_sorted(e.keys.begin() + std::ptrdiff_t(first), e.keys.end())) {
      row_entries.clear();
      for (std::size_t k = first; k < e.keys.size(); ++k)
        row_entries.emplace_back(e.keys[k], e.values[k]);
      std::sort(row_entries.begin(), row_entries.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      for (std::size_t k = first; k < e.keys.size(); ++k)
        e.keys[k] = row_entries[k - first].first, e.values[k] = row_entries[k - first].second;
    }
  }
  if (distributed) send_to_owners(comm, foreign_owners, foreign_keys, mirror_keys);
  std::sort(mirror_keys.begin(), mirror_keys.end());
  e.keys.insert(e.keys.end(), mirror_keys.begin(), mirror_keys.end());
  e.values.resize(e.keys.size(), 0.0);
  e.sorted_prefix =
      std::size_t(std::is_sorted_until(e.keys.begin(), e.keys.end()) - e.keys.begin());
  return e;
}

std::vector<double> gather_to_root(const MumpsNumbering& numbering, const Vector& b) {
  const LO n_local = LO(b.getLocalLength());
  Vector b_source(numbering.source), b_root(numbering.root);
  {
    auto from = b.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto to = b_source.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (LO i = 0; i < n_local; ++i) to(i, 0) = from(i, 0);
  }
  b_root.doExport(b_source, *numbering.to_root, Tpetra::INSERT);
  std::vector<double> on_root(b_root.getLocalLength());
  auto r = b_root.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t i = 0; i < on_root.size(); ++i) on_root[i] = r(i, 0);
  return on_root;
}

void scatter_from_root(const MumpsNumbering& numbering, const std::vector<double>& on_root,
                       Vector& x) {
  Vector x_source(numbering.source), x_root(numbering.root);
  {
    auto r = x_root.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t i = 0; i < on_root.size(); ++i) r(i, 0) = on_root[i];
  }
  x_source.doImport(x_root, *numbering.to_root, Tpetra::INSERT);
  const LO n_local = LO(x.getLocalLength());
  auto from = x_source.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto to = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (LO i = 0; i < n_local; ++i) to(i, 0) = from(i, 0);
}

}  // namespace grout
