#pragma once
// The contact terms of the (u, λ) system and their exchange between ranks: the one place where
// contact contributions cross rank boundaries (docs/design.md, "Distributed contact").
//
// A rank evaluates the slave nodes it owns. Their terms reach displacement rows that other
// ranks may own (the master rows −M_jl λ_j), so every term carries a tag (interface, slave
// node) and, in the Jacobian, its emission index within the tag. The owner of a row sums the
// row's terms in tag (and emission) order, whatever rank computed them: F and J then have the
// same bits on any number of ranks.

#include <mpi.h>

#include <map>
#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// One Jacobian term J(row, col) += value. `key` orders the terms of one row: equal
/// (row, col) terms are summed in key order, whatever order they come in.
struct JacobianTerm {
  GO row, col;
  long long key;
  double value;
};

class ContactTerms {
 public:
  /// Forget the terms of the last evaluation.
  void clear();
  /// The terms that follow belong to `tag` (interface and slave node: tags order the sums).
  void begin_node(long long tag);
  /// F(row) += value on a displacement row (any rank's).
  void add_force(GO row, double value);
  /// J(row, col) += value (any rank's row); exact zeros are dropped. Throws std::logic_error
  /// past 2^24 terms for one tag.
  void add_entry(GO row, GO col, double value);

  /// Sends the force terms of other ranks' rows to their owners, sums the terms of each owned
  /// row in tag order and adds the sum to F (on `map`). Records the owners of the remote rows
  /// for owned_entries(). Collective.
  void sum_forces_to_owners(const Map& map, MPI_Comm comm, Vector& F);
  /// This rank's Jacobian terms: those of its own rows, then those other ranks computed for
  /// them, in rank order. Needs sum_forces_to_owners() of the same evaluation. Collective.
  std::vector<JacobianTerm> owned_entries(const Map& map, MPI_Comm comm) const;

 private:
  std::vector<GO> force_rows_;
  std::vector<long long> force_tags_;
  std::vector<double> force_values_;
  std::vector<GO> entry_rows_, entry_cols_;
  std::vector<long long> entry_keys_;  ///< tag · 2^24 + emission index: the insertion order
  std::vector<double> entry_values_;
  std::map<GO, int> remote_owner_;  ///< owner of each row of another rank in the terms
  long long tag_ = 0;               ///< tag of the node being evaluated
  long long seq_ = 0;               ///< entries emitted for it so far
};

}  // namespace grout
