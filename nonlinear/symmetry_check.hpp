#pragma once
// Two pieces of the symmetric reduction (symmetric_condensation.hpp) that talk to other ranks:
// the check that J's displacement block is symmetric, and the all-to-all of matrix entries it
// and the reduced matrix's assembly send to the ranks that own their rows.

#include <string>
#include <unordered_map>
#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// |K_ij − K_ji| above this times row i's largest |entry|: K is not symmetric.
constexpr double symmetry_tolerance = 1e-12;

/// A matrix entry sent to another rank.
struct Triple {
  GO row, col;
  double value;
};

/// Sends out[r] to rank r; returns what the ranks sent here, in rank order (collective: one
/// MPI_Alltoall of the sizes, one MPI_Alltoallv of the entries).
std::vector<Triple> send_to_ranks(const Comm& comm, const std::vector<std::vector<Triple>>& out);

/// Checks that J's displacement block (rows and columns that are no paired multiplier,
/// `by_lambda`'s keys) is symmetric: |J_ij − J_ji| ≤ symmetry_tolerance × max_k |J_ik|
/// (collective). Returns the first offending entry on this rank, or an empty string.
std::string check_symmetric(const Matrix& J, const std::unordered_map<GO, int>& by_lambda);

}  // namespace grout
