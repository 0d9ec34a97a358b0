#pragma once
// Rows of an assembled Tpetra system gathered by global id, for the multiplier condensations
// (condensed_solve.hpp, symmetric_condensation.hpp): they look at a slave node's rows, and at
// rows of other ranks' dofs, as plain (columns, values, right-hand side) records.

#include <unordered_map>
#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// One row of J x = b: its nonzero entries (global columns; exact zeros dropped) and b's entry.
struct Row {
  std::vector<GO> cols;
  std::vector<double> vals;
  double rhs = 0.0;
};

using RowTable = std::unordered_map<GO, Row>;

/// The locally stored rows of a fill-complete matrix A (and b), by global row.
void add_rows(const Matrix& A, const Vector& b, RowTable& table);
/// Rows `gids` of A and b, each owned by this rank (not collective).
/// \pre every id in `gids` is in A's row map on this rank (std::out_of_range otherwise).
void add_owned_rows(const Matrix& A, const Vector& b, const std::vector<GO>& gids, RowTable& table);
/// Rows `gids` of J and b on this rank (collective; gids may be owned elsewhere).
void import_rows(const Matrix& J, const Vector& b, std::vector<GO> gids, RowTable& table);

}  // namespace grout
