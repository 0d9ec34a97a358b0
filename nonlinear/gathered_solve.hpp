#pragma once
// A direct solve done on rank 0 with the system gathered there (LinearSolver's 2D default,
// `MUMPS: {gather: true}`, and `type: amesos2`): the same matrix, entry for entry and in the
// same order, on any number of ranks, so the same answer bit for bit (docs/performance.md,
// "2D speed and the demo on 2 ranks").

#include <mpi.h>
#include <Teuchos_DefaultMpiComm.hpp>
#include <algorithm>
#include <climits>
#include <stdexcept>
#include <string>
#include <vector>

#include "assembly/raw_mpi_comm.hpp"
#include "assembly/tpetra_types.hpp"

namespace grout {
namespace gathered_solve_detail {

// Direct solve on rank 0: gather K's rows and b to rank 0 (plain arrays, one gatherv each),
// build there the whole matrix on rank 0's 1-rank communicator `self` (KLU2 is only trusted
// there), with the rows in global-id order and each row's entries in column order, call
// solve_on_root(K, b, x) on it, broadcast x. The matrix built is the same, entry for entry
// and in the same order, on any number of ranks (Grout's global ids do not depend on the
// partition). A failure on rank 0 (e.g. a singular matrix) is thrown on every rank alike, so
// that Newton cuts the step back everywhere.
template <class SolveOnRoot>
void solve_gathered(const Teuchos::RCP<const Matrix>& K, const Vector& b, Vector& x,
                    const Teuchos::RCP<const Comm>& self, SolveOnRoot&& solve_on_root) {
  const auto comm = K->getRowMap()->getComm();
  const int ranks = comm->getSize();
  const bool root = comm->getRank() == 0;
  const auto& row_map = *K->getRowMap();
  const auto& col_map = *K->getColMap();
  const auto local = K->getLocalMatrixHost();
  const LO n_local = LO(row_map.getNodeNumElements());
  const GO n = GO(row_map.getGlobalNumElements());
  if (n >= GO(INT_MAX) || GO(local.nnz()) >= GO(INT_MAX))
    throw std::runtime_error("gathered direct solve: more than 2^31 unknowns or entries");
  if (row_map.getMinAllGlobalIndex() != 0 || row_map.getMaxAllGlobalIndex() != n - 1)
    throw std::logic_error("gathered direct solve: the row map's global ids must be 0 .. n-1");

  // This rank's rows (global id, entry count), right-hand side and entries.
  std::vector<GO> my_rows(2 * std::size_t(n_local)), my_cols(local.nnz());
  std::vector<double> my_b(static_cast<std::size_t>(n_local)), my_values(local.nnz());
  {
    auto bv = b.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO i = 0; i < n_local; ++i) {
      my_rows[2 * std::size_t(i)] = row_map.getGlobalElement(i);
      my_rows[2 * std::size_t(i) + 1] = GO(local.graph.row_map(i + 1) - local.graph.row_map(i));
      my_b[std::size_t(i)] = bv(i, 0);
    }
    for (std::size_t p = 0; p < local.nnz(); ++p) {
      my_cols[p] = col_map.getGlobalElement(local.graph.entries(p));
      my_values[p] = local.values(p);
    }
  }
  const MPI_Comm mpi = raw_mpi_comm(*comm);
  const int my_counts[2] = {int(n_local), int(local.nnz())};
  std::vector<int> counts(root ? 2 * static_cast<std::size_t>(ranks) : 0);
  MPI_Gather(my_counts, 2, MPI_INT, counts.data(), 2, MPI_INT, 0, mpi);
  std::vector<int> row_counts(static_cast<std::size_t>(ranks)),
      row_displs(static_cast<std::size_t>(ranks)), pair_counts(static_cast<std::size_t>(ranks)),
      pair_displs(static_cast<std::size_t>(ranks)), entry_counts(static_cast<std::size_t>(ranks)),
      entry_displs(static_cast<std::size_t>(ranks));
  long long total_rows = 0, total_entries = 0;
  if (root) {
    for (int r = 0; r < ranks; ++r) {
      row_counts[r] = counts[2 * r], entry_counts[r] = counts[2 * r + 1];
      pair_counts[r] = 2 * row_counts[r];
      row_displs[r] = int(total_rows), pair_displs[r] = int(2 * total_rows);
      entry_displs[r] = int(total_entries);
      total_rows += row_counts[r], total_entries += entry_counts[r];
    }
  }
  std::vector<GO> all_rows(root ? 2 * std::size_t(total_rows) : 0),
      all_cols(root ? std::size_t(total_entries) : 0);
  std::vector<double> all_b(root ? std::size_t(total_rows) : 0),
      all_values(root ? std::size_t(total_entries) : 0);
  MPI_Gatherv(my_rows.data(), 2 * n_local, MPI_LONG_LONG, all_rows.data(), pair_counts.data(),
              pair_displs.data(), MPI_LONG_LONG, 0, mpi);
  MPI_Gatherv(my_b.data(), n_local, MPI_DOUBLE, all_b.data(), row_counts.data(), row_displs.data(),
              MPI_DOUBLE, 0, mpi);
  MPI_Gatherv(my_cols.data(), my_counts[1], MPI_LONG_LONG, all_cols.data(), entry_counts.data(),
              entry_displs.data(), MPI_LONG_LONG, 0, mpi);
  MPI_Gatherv(my_values.data(), my_counts[1], MPI_DOUBLE, all_values.data(), entry_counts.data(),
              entry_displs.data(), MPI_DOUBLE, 0, mpi);

  std::string failure;
  std::vector<double> x_all(std::size_t(n), 0.0);
  if (root) {
    // Rows in global-id order: start of each gathered row, and the CSR row pointers.
    std::vector<std::size_t> start(std::size_t(n), 0);
    Kokkos::View<std::size_t*> row_ptr("grout::direct_rows", n + 1);
    for (std::size_t i = 0, p = 0; i < std::size_t(total_rows); ++i) {
      const GO row = all_rows[2 * i], length = all_rows[2 * i + 1];
      start[std::size_t(row)] = p;
      row_ptr(row + 1) = std::size_t(length);
      p += std::size_t(length);
    }
    for (GO i = 0; i < n; ++i) row_ptr(i + 1) += row_ptr(i);
    Kokkos::View<LO*> cols("grout::direct_cols", std::size_t(total_entries));
    Kokkos::View<double*> values("grout::direct_vals", std::size_t(total_entries));
    Vector b_self(Teuchos::rcp(new Map(n, n, 0, self))), x_self(b_self.getMap());
    {
      auto bs = b_self.getLocalViewHost(Tpetra::Access::OverwriteAll);
      std::vector<std::pair<GO, double>> row_entries;
      for (std::size_t i = 0; i < std::size_t(total_rows); ++i) {
        const GO row = all_rows[2 * i];
        bs(row, 0) = all_b[i];
      }
      for (GO row = 0; row < n; ++row) {
        const std::size_t from = start[std::size_t(row)];
        const std::size_t length = row_ptr(row + 1) - row_ptr(row);
        row_entries.clear();
        for (std::size_t k = 0; k < length; ++k)
          row_entries.emplace_back(all_cols[from + k], all_values[from + k]);
        std::sort(row_entries.begin(), row_entries.end(),
                  [](const auto& a, const auto& c) { return a.first < c.first; });
        for (std::size_t k = 0; k < length; ++k) {
          cols(row_ptr(row) + k) = LO(row_entries[k].first);
          values(row_ptr(row) + k) = row_entries[k].second;
        }
      }
    }
    const auto map = b_self.getMap();
    auto K_self = Teuchos::rcp(new Matrix(map, map, row_ptr, cols, values));
    K_self->fillComplete(map, map);
    try {
      solve_on_root(K_self, b_self, x_self);
      auto xs = x_self.getLocalViewHost(Tpetra::Access::ReadOnly);
      for (GO i = 0; i < n; ++i) x_all[std::size_t(i)] = xs(i, 0);
    } catch (const std::exception& e) {
      failure = e.what();
      if (failure.empty()) failure = "direct solve failed";
    }
  }
  int length = int(failure.size());
  Teuchos::broadcast(*comm, 0, Teuchos::outArg(length));
  if (length > 0) {
    failure.resize(std::size_t(length));
    Teuchos::broadcast(*comm, 0, length, &failure[0]);
    throw std::runtime_error(failure);
  }
  if (ranks > 1) MPI_Bcast(x_all.data(), int(n), MPI_DOUBLE, 0, mpi);
  auto xv = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (LO i = 0; i < n_local; ++i) xv(i, 0) = x_all[std::size_t(row_map.getGlobalElement(i))];
}

}  // namespace gathered_solve_detail

using gathered_solve_detail::solve_gathered;

}  // namespace grout
