#pragma once
// A fill-complete Tpetra matrix from CSR arrays a caller has built in local indices (the
// Jacobian, jacobian_matrix.cpp; the symmetric reduction's K̃, symmetric_condensation.cpp):
// one copy into the Kokkos views the matrix keeps, and no insertGlobalValues, sorting or
// column-map search.

#include <cstddef>
#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// The matrix on `row_map` × `col_map` whose row i holds columns ind[ptr[i]..ptr[i+1]) (local
/// indices of `col_map`) with values val[...]; fill-complete on (`domain`, `range`) by
/// expertStaticFillComplete, which skips Tpetra's checks: \pre each row sorted by column, no
/// column twice in a row, ptr.size() = rows + 1, ind.size() = val.size() = ptr.back().
/// Collective (the fill builds the Import from `domain` to `col_map`).
Teuchos::RCP<Matrix> local_csr_matrix(const Teuchos::RCP<const Map>& row_map,
                                      const Teuchos::RCP<const Map>& col_map,
                                      const std::vector<std::size_t>& ptr,
                                      const std::vector<LO>& ind, const std::vector<double>& val,
                                      const Teuchos::RCP<const Map>& domain,
                                      const Teuchos::RCP<const Map>& range);

/// The views the matrix keeps: row offsets, column indices, values.
using CsrRowOffsets = Matrix::local_graph_device_type::row_map_type::non_const_type;
using CsrColumns = Matrix::local_graph_device_type::entries_type::non_const_type;
using CsrValues = Matrix::local_matrix_device_type::values_type;

/// As above from views built in place (host-accessible memory, as Grout's Serial node), kept
/// by the matrix without a copy: at 1e6 unknowns the copy of the Jacobian was 0.5 GB of fresh
/// pages a Newton iteration. `ind` and `val` may be longer than ptr(rows): the entries past
/// it are not the matrix's.
Teuchos::RCP<Matrix> local_csr_matrix(const Teuchos::RCP<const Map>& row_map,
                                      const Teuchos::RCP<const Map>& col_map, CsrRowOffsets ptr,
                                      CsrColumns ind, CsrValues val,
                                      const Teuchos::RCP<const Map>& domain,
                                      const Teuchos::RCP<const Map>& range);

/// CSR rows appended in order into the views the matrix will keep (no second copy): room for
/// `capacity` entries, grown by a quarter when an append needs more.
class CsrBuilder {
 public:
  CsrBuilder(LO rows, std::size_t capacity);
  /// Appends an entry to the current row (columns ascending within a row, each once).
  void append(LO column, double value) {
    if (nnz_ == columns_.extent(0)) grow();
    columns_(nnz_) = column;
    values_(nnz_) = value;
    ++nnz_;
  }
  /// Closes the current row; the next append opens the next. Throws std::logic_error past the
  /// last row.
  void end_row() {
    if (std::size_t(row_) + 1 >= offsets_.extent(0)) too_many_rows();
    offsets_(++row_) = nnz_;
  }
  std::size_t size() const { return nnz_; }
  /// The matrix, as local_csr_matrix, once every row is closed (throws std::logic_error
  /// otherwise); the builder is left empty.
  Teuchos::RCP<Matrix> matrix(const Teuchos::RCP<const Map>& row_map,
                              const Teuchos::RCP<const Map>& col_map,
                              const Teuchos::RCP<const Map>& domain,
                              const Teuchos::RCP<const Map>& range);

 private:
  void grow();
  [[noreturn]] void too_many_rows() const;
  CsrRowOffsets offsets_;
  CsrColumns columns_;
  CsrValues values_;
  std::size_t nnz_ = 0;
  LO row_ = 0;
};

}  // namespace grout
