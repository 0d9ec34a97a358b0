#include "drivers/root_gather.hpp"

#include <stdexcept>

#include "assembly/raw_mpi_comm.hpp"

namespace grout {

RootGather::RootGather(const Comm& comm, const std::vector<GlobalIndex>& ids, GlobalIndex size)
    : comm_(raw_mpi_comm(comm)), rank_(comm.getRank()), local_count_(int(ids.size())), size_(size) {
  const int ranks = comm.getSize();
  if (rank_ == 0) counts_.resize(ranks);
  MPI_Gather(&local_count_, 1, MPI_INT, counts_.data(), 1, MPI_INT, 0, comm_);
  if (rank_ == 0) {
    offsets_.assign(ranks, 0);
    long long total = 0;
    for (int r = 0; r < ranks; ++r) {
      offsets_[r] = int(total);
      total += counts_[r];
    }
    // An MPI displacement is an int: the whole variable must have fewer than 2^31 entries.
    if (total > 2147483647LL) throw std::length_error("RootGather: more than 2^31 entries");
    received_.resize(std::size_t(total));
  }
  static_assert(sizeof(GlobalIndex) == sizeof(long long), "MPI_LONG_LONG");
  MPI_Gatherv(ids.data(), local_count_, MPI_LONG_LONG, received_.data(), counts_.data(),
              offsets_.data(), MPI_LONG_LONG, 0, comm_);
}

std::vector<double> RootGather::gather(const std::vector<double>& values) const {
  if (int(values.size()) != local_count_)
    throw std::invalid_argument("RootGather::gather: one value per entry expected");
  std::vector<double> received(received_.size());
  MPI_Gatherv(values.data(), local_count_, MPI_DOUBLE, received.data(), counts_.data(),
              offsets_.data(), MPI_DOUBLE, 0, comm_);
  if (rank_ != 0 || size_ == 0) return received;
  std::vector<double> whole(std::size_t(size_), 0.0);
  for (std::size_t i = 0; i < received_.size(); ++i) whole[received_[i]] = received[i];
  return whole;
}

}  // namespace grout
