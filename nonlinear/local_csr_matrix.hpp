#pragma once
// A fill-complete Tpetra matrix from CSR rows a caller builds in local indices (the Jacobian,
// jacobian_matrix.cpp; the symmetric reduction's K̃, symmetric_condensation.cpp), written
// straight into the Kokkos views the matrix keeps: no insertGlobalValues, sorting, column-map
// search or copy (at 1e6 unknowns a copy of the Jacobian from vectors was 0.5 GB of fresh pages
// a Newton iteration; host-accessible memory, as Grout's Serial node).

#include <cstddef>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// The views the matrix keeps: row offsets, column indices, values.
using CsrRowOffsets = Matrix::local_graph_device_type::row_map_type::non_const_type;
using CsrColumns = Matrix::local_graph_device_type::entries_type::non_const_type;
using CsrValues = Matrix::local_matrix_device_type::values_type;

/// CSR rows appended in order: room for `capacity` entries, grown by a quarter when an append
/// needs more.
class CsrBuilder {
 public:
  CsrBuilder(LO rows, std::size_t capacity);
  /// Appends an entry (a local column of the matrix's column map) to the current row: \pre
  /// columns ascending within a row, each once (the fill skips Tpetra's checks).
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
  /// The matrix on `row_map` × `col_map`, fill-complete on (`domain`, `range`) by
  /// expertStaticFillComplete, once every row is closed (throws std::logic_error otherwise);
  /// the builder is left empty. Collective (the fill builds the Import from `domain` to
  /// `col_map`).
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
