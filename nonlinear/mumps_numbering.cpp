#include "nonlinear/mumps_numbering.hpp"

#include <algorithm>

namespace grout {

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
    const auto importer = K.getGraph()->getImporter();
    if (!importer.is_null() && K.getDomainMap()->isSameAs(*row_map)) {
      col_values.doImport(row_values, *importer, Tpetra::INSERT);
    } else {
      col_values.doImport(row_values, Import(row_map, K.getColMap()), Tpetra::INSERT);
    }
    auto c = col_values.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t j = 0; j < e.column_index.size(); ++j)
      e.column_index[j] = (long long)(c(j, 0));
  }

  const auto local = K.getLocalMatrixHost();
  std::vector<long long> mirror_keys;
  e.keys.reserve(local.nnz());
  e.values.reserve(local.nnz());
  for (LO i = 0; i < n_local; ++i) {
    const long long row = e.row_index[std::size_t(i)];
    for (auto p = local.graph.row_map(i); p < local.graph.row_map(i + 1); ++p) {
      const long long col = e.column_index[local.graph.entries(p)];
      if (symmetric && col > row) {
        // The mirror keys go last, after the rows' own (in row order, on one rank sorted:
        // found in one forward walk instead of a binary search each; mumps_pattern.hpp).
        if (local.values(p) == 0.0) mirror_keys.push_back(col * n + row);
        continue;
      }
      e.keys.push_back(row * n + col);
      e.values.push_back(local.values(p));
    }
  }
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
