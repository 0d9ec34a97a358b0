#pragma once
// MumpsSolver's second phase (nonlinear/mumps_solver.hpp): the sparsity pattern that MUMPS
// analysed (ordering, symbolic factorisation), kept while the matrices' patterns stay inside
// it.
//
// The Jacobian's pattern follows the contact state (active set, mortar pairs, nonzero
// derivatives) and changes between Newton iterations, mostly within what earlier iterations
// had. Entries of the analysed pattern that a matrix lacks are explicit zeros. A new entry
// leads to a new analysis of the union of both patterns, or of the new pattern alone if the
// union would be more than twice its size.

#include <mpi.h>

#include <cstddef>
#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// This rank's part of the analysed pattern.
struct MumpsPattern {
  /// Sorted unique keys row · n + col (0-based, MUMPS numbering), and MUMPS's 1-based row and
  /// column indices in that order.
  std::vector<long long> keys;
  std::vector<int> irn, jcn;
  /// The last matrix's entry keys (mumps_numbering.hpp, storage order) and their positions in
  /// `keys`: an unchanged matrix pattern skips the search.
  std::vector<long long> last_keys;
  std::vector<std::size_t> position;
};

/// Whether `keys` (the sorted_prefix first in increasing order) has a key outside `pattern`,
/// on any rank; `valid`: the pattern is analysed in this numbering (false: missing). Sets
/// pattern.position when nothing is missing. Collective.
bool pattern_misses(MumpsPattern& pattern, bool valid, const std::vector<long long>& keys,
                    std::size_t sorted_prefix, MPI_Comm comm);

/// A new pattern for `keys` (n global rows): the union with the old one if `valid` and at most
/// twice the keys' size on every rank, else the keys alone; irn, jcn and position with it.
/// Collective.
void rebuild_pattern(MumpsPattern& pattern, bool valid, const std::vector<long long>& keys,
                     std::size_t sorted_prefix, GO n, MPI_Comm comm);

/// The entries' values summed into pattern order (zeros where the matrix has no entry).
std::vector<double> values_in_pattern(const MumpsPattern& pattern,
                                      const std::vector<double>& entry_values);

}  // namespace grout
