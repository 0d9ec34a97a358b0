#pragma once
// MumpsSolver's first phase (nonlinear/mumps_solver.hpp): MUMPS's global numbering of a
// distributed Tpetra matrix, this rank's entries in it, and the right-hand side gathered to
// rank 0 and the solution scattered back.
//
// Numbering: when the row map's global ids are 0 .. n−1 (Grout's maps: node · dim + component,
// then the multipliers in slave-node order) they are used as they are, so that MUMPS sees the
// same matrix, and so makes the same ordering and pivot sequence, on any number of ranks.
// Otherwise a contiguous renumbering: this rank's rows offset .. offset + n_local − 1 in the
// row map's local order.

#include <mpi.h>

#include <cstddef>
#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// The numbering of the last matrix's row map and the maps that move vectors to rank 0.
struct MumpsNumbering {
  GO n = -1;                             ///< global rows
  bool gid_numbering = false;            ///< the row map's global ids are MUMPS's indices
  Teuchos::RCP<const Map> source, root;  ///< row map (or its renumbering); all rows on rank 0
  Teuchos::RCP<Export> to_root;          ///< source → root
};

/// Sets `numbering` for `row_map` (n global rows) unless it already fits it. Returns true, on
/// every rank alike, when it changed: an analysed pattern is then in the old numbering.
/// Collective.
bool renumber(MumpsNumbering& numbering, const Teuchos::RCP<const Map>& row_map, MPI_Comm comm);

/// This rank's entries of K in MUMPS's numbering, 0-based, as keys row · n + col in increasing
/// order (rows by MUMPS index, each row's keys sorted), with their values. With `symmetric` only
/// the lower triangle (col ≤ row); an explicit zero above the diagonal stands for its mirror's
/// place in the pattern (symmetric_condensation.hpp keeps the pattern of rows it eliminates that
/// way, on the rank owning the row only) and adds the key (col, row) with value 0, after the rows'
/// own (sorted among themselves), on the rank owning row col: every key then lives on its row's
/// owner alone, so that a rank's pattern is the global pattern's part in its rows and an entry that
/// appears in a later matrix is new on its rank only if it is new to the matrix (else 2 ranks
/// analysed 5 times where 1 rank analysed 3 times on the 3D Hertz spheres). Collective when
/// `symmetric`.
struct MumpsEntries {
  std::vector<long long> row_index;     ///< MUMPS index of every owned row
  std::vector<long long> column_index;  ///< MUMPS index of every column of K's column map
  std::vector<long long> keys;
  std::vector<double> values;
  std::size_t sorted_prefix = 0;  ///< keys[0 .. sorted_prefix) are increasing
};
MumpsEntries mumps_entries(const MumpsNumbering& numbering, const Matrix& K, bool symmetric);

/// b (on the row map) gathered to rank 0 in MUMPS's numbering: n values there, none elsewhere.
/// Collective.
std::vector<double> gather_to_root(const MumpsNumbering& numbering, const Vector& b);
/// x (on the row map) ← the solution `on_root` (n values on rank 0). Collective.
void scatter_from_root(const MumpsNumbering& numbering, const std::vector<double>& on_root,
                       Vector& x);

}  // namespace grout
