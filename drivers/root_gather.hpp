#pragma once
// Results to rank 0 one variable at a time: each rank gives the values of its own entries
// (owned nodes or elements, by global index) and rank 0 receives them in one MPI_Gatherv and
// puts them in global order. Memory: the global index of every entry on rank 0 (kept),
// the variable being written there, and the owned entries elsewhere: never a whole-mesh
// array on every rank.

#include <mpi.h>

#include <vector>

#include "assembly/tpetra_types.hpp"
#include "io/mesh.hpp"

namespace grout {

class RootGather {
 public:
  /// Collective. `ids`: the global index of each of this rank's entries, each index given by
  /// one rank at most. `size`: the length of the whole variable (indices no rank gives are 0);
  /// 0 keeps the values in the order received (rank 0, then rank 1, ...) instead.
  RootGather(const Comm& comm, const std::vector<GlobalIndex>& ids, GlobalIndex size);

  /// Collective: `values[k]` belongs to ids[k]. Rank 0 gets the whole variable (or the
  /// values in the order received when size is 0); the other ranks an empty vector.
  std::vector<double> gather(const std::vector<double>& values) const;

  /// Rank 0: the global index of each value in the order received (empty elsewhere).
  const std::vector<GlobalIndex>& received_ids() const { return received_; }

 private:
  MPI_Comm comm_;
  int rank_ = 0;
  int local_count_ = 0;
  GlobalIndex size_ = 0;
  std::vector<int> counts_, offsets_;  ///< rank 0: entries of each rank, and where they go
  std::vector<GlobalIndex> received_;  ///< rank 0
};

}  // namespace grout
